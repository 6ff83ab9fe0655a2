#!/usr/bin/env python3
"""GetFEM (Debian python3-getfem 5.4.2) as an external code of contact-suite's solver protocol.

Solves one case directory (docs/solver-protocol.md): plane strain, linear elasticity of the
deformable body against the rigid target's analytic profile, with one of GetFEM's contact bricks
for a rigid obstacle, chosen by the option label:

  nodal_al     add_nodal_contact_with_rigid_obstacle_brick (nodal augmented Lagrangian,
               Alart-Curnier, non-symmetric; multipliers = nodal contact forces)
  integral_al  add_integral_contact_with_rigid_obstacle_brick (integral augmented Lagrangian,
               option 1; the multiplier a contact stress on the boundary's Lagrange FEM)
  penalty      add_penalized_contact_with_rigid_obstacle_brick (penalty r = 50 E / h)
  nitsche      add_Nitsche_contact_with_rigid_obstacle_brick (theta = 1, gamma0 = E / h... see
               GAMMA0 below)

Porting notes (also in docs/solver-protocol.md):
  - node order: our quadrilaterals are counter-clockwise (Q8: corners, then mid-sides); GetFEM's
    QK geometric transformations number their nodes lexicographically (Q4: 0 1 3 2; the 8-node
    GT_Q2_INCOMPLETE(2): 0 4 1 7 5 3 6 2 of ours);
  - the vertical mode: with a rigid target the block is held in z by the contact alone (H, F,
    P); Newton from u = 0 with every contact inactive meets a singular tangent, so u starts as a
    rigid translation of the block onto the obstacle (every contact node a little in contact);
  - nodal pressure: the nodal brick's multipliers are nodal forces, divided here by each node's
    tributary length on the contact surface; the integral brick's multiplier is a stress field,
    read at the nodes. Penalty and Nitsche give no pressure of their own (none is written).

Usage: getfem_case.py CASE_DIR OPTION     (writes the result files into CASE_DIR)
       getfem_case.py --version
"""
import json
import math
import os
import sys

import numpy as np

OPTIONS = ("nodal_al", "integral_al", "penalty", "nitsche")
PENALTY_FKN = 50.0  # penalty stiffness r = FKN E / h (CalculiX's HARD contact: K = 50 E)
GAMMA0_FKN = 50.0  # Nitsche: gamma = gamma0 / h with gamma0 = FKN E
AL_FKN = 1.0  # augmentation parameter r = FKN E / h (GetFEM's guide: close to E)


class CaseError(Exception):
    """A case this adapter cannot solve: the message is the reason."""


# ---- mesh.msh ---------------------------------------------------------------------------------

def read_msh(path):
    """Nodes {id: (x, z)}, elements {body_tag: [node ids in our order]}, line sets
    {name: [[ids]]}, node sets {name: [ids]} from our Gmsh MSH 4.1 ASCII file."""
    with open(path) as f:
        lines = f.read().split("\n")
    names = {}
    at = lines.index("$PhysicalNames")
    for row in lines[at + 2:at + 2 + int(lines[at + 1])]:
        dim, tag, name = row.split(" ", 2)
        names[(int(dim), int(tag))] = name.strip('"')
    at = lines.index("$Nodes")
    nodes = {}
    pos = at + 2
    for _ in range(int(lines[at + 1].split()[0])):
        count = int(lines[pos].split()[3])
        tags = [int(t) for t in lines[pos + 1:pos + 1 + count]]
        for k, tag in enumerate(tags):
            x, y, _ = (float(v) for v in lines[pos + 1 + count + k].split())
            nodes[tag] = (x, y)
        pos += 1 + 2 * count
    at = lines.index("$Elements")
    groups = {}
    pos = at + 2
    for _ in range(int(lines[at + 1].split()[0])):
        dim, tag, _, count = (int(v) for v in lines[pos].split())
        rows = [[int(v) for v in r.split()[1:]] for r in lines[pos + 1:pos + 1 + count]]
        groups.setdefault((dim, names[(dim, tag)]), []).extend(rows)
        pos += 1 + count
    return nodes, groups


# ---- the obstacle -----------------------------------------------------------------------------

def obstacle_expression(profile):
    """The signed distance (> 0 outside the rigid region) in GetFEM's language, valid on the
    deformable body's side of the profile (x, y are GetFEM's coordinates: our x, z)."""
    kind = profile["type"]
    if kind == "plane":
        (px, pz), (nx, nz) = profile["point"], profile["normal"]
        return f"(x-({px!r}))*({nx!r})+(y-({pz!r}))*({nz!r})"
    if kind == "circle":
        (cx, cz), r = profile["center"], profile["radius"]
        return f"sqrt(sqr(x-({cx!r}))+sqr(y-({cz!r})))-({r!r})"
    (cx, cz), (dx, dz) = profile["face_center"], profile["direction"]
    h = f"((x-({cx!r}))*({dx!r})+(y-({cz!r}))*({dz!r}))"
    s = f"abs((x-({cx!r}))*({dz!r})-(y-({cz!r}))*({dx!r}))"
    if kind == "rounded_flat_punch":
        b, re_ = profile["half_width_b"], profile["edge_radius_re"]
        return f"sqrt(sqr(max({s}-({b!r}),0))+sqr({h}+({re_!r})))-({re_!r})"
    if kind == "sharp_flat_punch":
        a = profile["half_width_a"]
        return f"sqrt(sqr(max({s}-({a!r}),0))+sqr({h}))"
    raise CaseError(f"unknown rigid profile '{kind}'")


def obstacle_values(profile, pts):
    """The same signed distance at points pts (2 x n), with numpy."""
    x, z = pts[0], pts[1]
    kind = profile["type"]
    if kind == "plane":
        (px, pz), (nx, nz) = profile["point"], profile["normal"]
        return (x - px) * nx + (z - pz) * nz
    if kind == "circle":
        (cx, cz), r = profile["center"], profile["radius"]
        return np.hypot(x - cx, z - cz) - r
    (cx, cz), (dx, dz) = profile["face_center"], profile["direction"]
    h = (x - cx) * dx + (z - cz) * dz
    s = np.abs((x - cx) * dz - (z - cz) * dx)
    if kind == "rounded_flat_punch":
        b, re_ = profile["half_width_b"], profile["edge_radius_re"]
        return np.hypot(np.maximum(s - b, 0.0), h + re_) - re_
    a = profile["half_width_a"]
    return np.hypot(np.maximum(s - a, 0.0), h)


# ---- the model --------------------------------------------------------------------------------

# Our counter-clockwise order -> GetFEM's lexicographic QK order.
Q4_TO_GETFEM = (0, 1, 3, 2)
Q8_TO_GETFEM = (0, 4, 1, 7, 5, 3, 6, 2)


class Case:
    def __init__(self, case_dir):
        with open(os.path.join(case_dir, "case.json")) as f:
            self.json = json.load(f)
        j = self.json
        if j.get("format_version") != 1:
            raise CaseError(f"case.json format_version {j.get('format_version')} is not 1")
        if j["analysis"] != "plane_strain":
            raise CaseError("not supported by getfem adapter: axisymmetric analysis (the "
                            "r-weighted weak form is not written)")
        target = j["contact_pair"]["target"]
        if target["kind"] != "rigid":
            raise CaseError("not supported by getfem adapter: a meshed target")
        self.profile = target["profile"]
        self.nodes, self.groups = read_msh(os.path.join(case_dir, j["mesh"]["file"]))
        self.q8 = j["mesh"]["element"] == "Q8"
        body = next(b for b in j["bodies"] if b["role"] == "deformable")
        self.E, self.nu = body["E"], body["nu"]
        self.elements = self.groups[(2, body["name"])]
        ids = sorted({n for e in self.elements for n in e})
        self.node_ids = ids


def node_sets(case):
    """Node ids of every node set by name: an edge set's nodes, unless a point group of the
    name (or "<name>:nodes", a node set that differs from its edge set) says otherwise."""
    out = {}
    for dim in (1, 0):
        for (d, name), rows in case.groups.items():
            if d == dim:
                out[name.removesuffix(":nodes")] = sorted({n for r in rows for n in r})
    return out


def build(case, option):
    import getfem as gf

    gf.util_trace_level(0)
    gf.util_warning_level(0)
    mesh = gf.Mesh("empty", 2)
    gt = gf.GeoTrans("GT_Q2_INCOMPLETE(2)" if case.q8 else "GT_QK(2,1)")
    order = Q8_TO_GETFEM if case.q8 else Q4_TO_GETFEM
    for e in case.elements:
        pts = np.array([case.nodes[e[k]] for k in order]).T
        mesh.add_convex(gt, pts)
    fem = gf.Fem("FEM_Q2_INCOMPLETE(2)" if case.q8 else "FEM_QK(2,1)")
    mfu = gf.MeshFem(mesh, 2)
    mfu.set_fem(fem)
    mim = gf.MeshIm(mesh, gf.Integ("IM_GAUSS_PARALLELEPIPED(2,%d)" % (6 if case.q8 else 4)))
    return gf, mesh, mfu, mim


def dof_index(mfu, case):
    """(dof of u_x, dof of u_z) of every node id, by coordinates."""
    pts = mfu.basic_dof_nodes()
    index = {}
    for d in range(pts.shape[1]):
        index.setdefault((round(pts[0, d], 12), round(pts[1, d], 12)), []).append(d)
    out = {}
    for n in case.node_ids:
        x, z = case.nodes[n]
        dofs = index.get((round(x, 12), round(z, 12)))
        if dofs is None or len(dofs) != 2:
            raise CaseError(f"node {n} at ({x}, {z}) has no GetFEM degrees of freedom")
        out[n] = (dofs[0], dofs[1])
    return out


def region_of(mesh, case, edge_set, rnum):
    pts = mesh.pts()
    coords = {(round(pts[0, i], 12), round(pts[1, i], 12)): i for i in range(pts.shape[1])}
    ids = sorted({n for r in case.groups[(1, edge_set)] for n in r})
    pids = [coords[(round(case.nodes[n][0], 12), round(case.nodes[n][1], 12))] for n in ids]
    faces = mesh.faces_from_pid(pids)
    mesh.set_region(rnum, faces)
    return ids


def tributary_lengths(case, edge_set):
    """Each node's share of the contact surface's length (lumped: half of each side; Q8 sides
    by Simpson's weights 1/6, 2/3, 1/6)."""
    out = {}
    for side in case.groups[(1, edge_set)]:
        a, b = case.nodes[side[0]], case.nodes[side[1]]
        length = math.hypot(b[0] - a[0], b[1] - a[1])
        weights = [1 / 6, 1 / 6, 2 / 3] if len(side) == 3 else [0.5, 0.5]
        for n, w in zip(side, weights):
            out[n] = out.get(n, 0.0) + w * length
    return out


def boundary_rows(case, dofs):
    """(dof, value) of every prescribed displacement, and the dofs of the load-controlled set."""
    fixed, controlled = {}, []
    sets = node_sets(case)
    for bc in case.json["boundary_conditions"]:
        component = 0 if bc["component"] == "x" else 1
        ids = [n for n in sets[bc["set"]] if n in dofs]
        if bc.get("load_controlled"):
            controlled += [dofs[n][component] for n in ids]
        elif "value" in bc:
            for n in ids:
                fixed[dofs[n][component]] = bc["value"]
        else:
            for n, v in bc["values"]:
                if n in dofs:
                    fixed[dofs[n][component]] = v
    return sorted(fixed.items()), controlled


def element_size(case, edge_set):
    """The smallest side length along the contact surface (h of the penalty and Nitsche)."""
    h = []
    for side in case.groups[(1, edge_set)]:
        a, b = case.nodes[side[0]], case.nodes[side[1]]
        h.append(math.hypot(b[0] - a[0], b[1] - a[1]))
    return min(h)


class Solution:
    def __init__(self):
        self.u = None
        self.iterations = 0
        self.converged = False
        self.reason = ""
        self.pressure = {}
        self.stress = None


def solve(case, option):
    gf, mesh, mfu, mim = build(case, option)
    dofs = dof_index(mfu, case)
    ndof = mfu.nbdof()
    E, nu = case.E, case.nu
    contact_set = case.json["contact_pair"]["contact_surface"]
    CONTACT = 1
    region_of(mesh, case, contact_set, CONTACT)
    h = element_size(case, contact_set)

    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_initialized_data("lambda", [E * nu / ((1 + nu) * (1 - 2 * nu))])
    md.add_initialized_data("mu", [E / (2 * (1 + nu))])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda", "mu")

    force = np.zeros(ndof)
    for n, fx, fz in case.json["loads"]["nodal_forces"]:
        if n in dofs:
            force[dofs[n][0]] += fx
            force[dofs[n][1]] += fz
    md.add_explicit_rhs("u", force)

    fixed, controlled = boundary_rows(case, dofs)
    rows = [d for d, _ in fixed] + controlled
    B = gf.Spmat("empty", len(rows), ndof)
    for i, d in enumerate(rows):
        B[i, d] = 1.0
    values = np.array([v for _, v in fixed] + [0.0] * len(controlled))
    md.add_variable("mult_bc", len(rows))
    bc_brick = md.add_constraint_with_multipliers("u", "mult_bc", B, values)

    # The obstacle as GetFEM data on the displacement's scalar FEM.
    mfd = gf.MeshFem(mesh, 1)
    mfd.set_fem(gf.Fem("FEM_Q2_INCOMPLETE(2)" if case.q8 else "FEM_QK(2,1)"))
    md.add_initialized_fem_data("obstacle", mfd, obstacle_values(case.profile, mfd.basic_dof_nodes()))
    if option == "nodal_al":
        contact_dofs = mfu.basic_dof_on_region(CONTACT)
        md.add_variable("lambda_n", len(contact_dofs) // 2)
        md.add_initialized_data("r", [AL_FKN * E / h])
        md.add_nodal_contact_with_rigid_obstacle_brick(
            mim, "u", "lambda_n", "r", CONTACT, obstacle_expression(case.profile), 1)
    elif option == "integral_al":
        mfl = gf.MeshFem(mesh, 1)
        mfl.set_fem(gf.Fem("FEM_Q2_INCOMPLETE(2)" if case.q8 else "FEM_QK(2,1)"))
        md.add_filtered_fem_variable("lambda_n", mfl, CONTACT)
        md.add_initialized_data("r", [AL_FKN * E / h])
        md.add_integral_contact_with_rigid_obstacle_brick(
            mim, "u", "lambda_n", "obstacle", "r", CONTACT, 1)
    elif option == "penalty":
        md.add_initialized_data("r", [PENALTY_FKN * E / h])
        md.add_penalized_contact_with_rigid_obstacle_brick(mim, "u", "obstacle", "r", CONTACT)
    elif option == "nitsche":
        md.add_initialized_data("gamma0", GAMMA0_FKN * E)
        # Without a friction coefficient GetFEM 5.4 builds a call of the friction projection
        # with the wrong arguments ("Wrong number or wrong size of arguments ... Coulomb_
        # friction_coupled_projection"): a zero coefficient is frictionless.
        md.add_initialized_data("friction_coeff", 0.0)
        md.add_Nitsche_contact_with_rigid_obstacle_brick(
            mim, "u", md.Neumann_term("u", CONTACT), "obstacle",
            "gamma0", CONTACT, 1.0, "friction_coeff")
    else:
        raise CaseError(f"unknown option '{option}' (known: {', '.join(OPTIONS)})")

    def run(delta):
        values[len(fixed):] = -delta
        md.set_private_rhs(bc_brick, values)
        # The vertical mode: start from the block translated onto the obstacle.
        md.set_variable("u", start_u(case, mfu, delta))
        nit, converged = solve_model(md)
        return nit, converged

    solution = Solution()
    control = case.json["load_control"]
    if control["kind"] == "total_load":
        solution.iterations, solution.converged = load_controlled(md, run, control, B, controlled)
    else:
        solution.iterations, solution.converged = run(0.0)
    u = md.variable("u")
    solution.u = {n: (u[dx], u[dz]) for n, (dx, dz) in dofs.items()}
    solution.stress = nodal_stresses(gf, md, mesh, mim, case, dofs)
    solution.pressure = contact_pressure(md, mfu, case, dofs, option, contact_set, CONTACT)
    return solution


def sigma_expression(E, nu):
    """Plane-strain Hooke's law in GetFEM's assembly language, the constants written out."""
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    return f"(({lam!r})*Trace(Grad_u)*Id(2)+({mu!r})*(Grad_u+Grad_u'))"


def start_u(case, mfu, delta):
    """A rigid translation of the block onto the obstacle by a small fraction of its load's
    elastic displacement (the vertical mode, see the file comment)."""
    u = np.zeros(mfu.nbdof())
    p = case.json["scales"]["p"]
    u[1::2] = -(p / case.E) * case.json["scales"]["length_unit"] * 1e-3 - delta
    return u


def solve_model(md):
    """Newton with GetFEM's default line search; (iterations, converged)."""
    out = md.solve("max_res", 1e-9, "max_iter", 100, "lsearch", "simplest")
    nit = int(out[0]) if np.ndim(out) else int(out)
    converged = bool(out[1]) if np.ndim(out) and len(out) > 1 else nit < 100
    return nit, converged


def load_controlled(md, run, control, B, controlled):
    """Secant iterations on the depth delta until the load-controlled set carries the total
    load (its z reaction: the multipliers of its constraint rows)."""
    target = control["total_load"]
    n_fixed = None
    total_it = 0

    def reaction():
        mult = md.variable("mult_bc")
        return float(np.sum(mult[len(mult) - len(controlled):]))

    d0 = control["depth_guess"]
    it, ok = run(d0)
    total_it += it
    f0 = abs(reaction())
    d1 = d0 * target / f0 if f0 > 0 else 2 * d0
    for _ in range(30):
        it, ok = run(d1)
        total_it += it
        f1 = abs(reaction())
        if not ok:
            return total_it, False
        if abs(f1 - target) <= 1e-10 * target:
            return total_it, True
        slope = (f1 - f0) / (d1 - d0)
        if not slope > 0:
            return total_it, False
        d0, f0, d1 = d1, f1, d1 + (target - f1) / slope
    return total_it, False


def nodal_stresses(gf, md, mesh, mim, case, dofs):
    """GetFEM's own nodal stresses: the element-wise L2 projection (Model.local_projection) of
    sigma onto a discontinuous FEM of the displacement's degree, averaged over the elements
    at each node. {node id: (sigma_x, sigma_z, tau_xz, sigma_out_of_plane)}."""
    mfs = gf.MeshFem(mesh, 1)
    mfs.set_fem(gf.Fem("FEM_Q2_INCOMPLETE_DISCONTINUOUS(2)" if case.q8 else
                       "FEM_QK_DISCONTINUOUS(2,1)"))
    exprs = {
        "sx": "lambda*Trace(Grad_u)+2*mu*Grad_u(1,1)",
        "sz": "lambda*Trace(Grad_u)+2*mu*Grad_u(2,2)",
        "txz": "mu*(Grad_u(1,2)+Grad_u(2,1))",
        "sy": "lambda*Trace(Grad_u)",
    }
    values = {k: md.local_projection(mim, e, mfs) for k, e in exprs.items()}
    pts = mfs.basic_dof_nodes()
    sums, counts = {}, {}
    for d in range(pts.shape[1]):
        key = (round(pts[0, d], 12), round(pts[1, d], 12))
        s = sums.setdefault(key, np.zeros(4))
        s += [values["sx"][d], values["sz"][d], values["txz"][d], values["sy"][d]]
        counts[key] = counts.get(key, 0) + 1
    out = {}
    for n in dofs:
        key = (round(case.nodes[n][0], 12), round(case.nodes[n][1], 12))
        out[n] = sums[key] / counts[key]
    return out


def contact_pressure(md, mfu, case, dofs, option, contact_set, region):
    """The code's own nodal contact pressure (> 0 in compression) where it gives one."""
    ids = sorted({n for r in case.groups[(1, contact_set)] for n in r})
    if option == "nodal_al":
        # One multiplier per node of the region, in the order of the region's z dofs; it is
        # the nodal contact force (<= 0 in compression): over the tributary length.
        forces = md.variable("lambda_n")
        region_dofs = mfu.basic_dof_on_region(region)
        z_dofs = [d for d in region_dofs if d % 2 == 1]
        node_of = {dz: n for n, (dx, dz) in dofs.items()}
        lengths = tributary_lengths(case, contact_set)
        return {node_of[d]: -forces[k] / lengths[node_of[d]] for k, d in enumerate(z_dofs)}
    if option == "integral_al":
        lam = md.variable("lambda_n")
        mfl = md.mesh_fem_of_variable("lambda_n")
        pts = mfl.basic_dof_nodes()
        at = {(round(pts[0, d], 12), round(pts[1, d], 12)): -lam[d] for d in range(len(lam))}
        return {n: at[(round(case.nodes[n][0], 12), round(case.nodes[n][1], 12))]
                for n in ids if (round(case.nodes[n][0], 12), round(case.nodes[n][1], 12)) in at}
    return {}


def write_results(case_dir, solution, version):
    with open(os.path.join(case_dir, "displacements.csv"), "w") as f:
        f.write("node_id,ux,uz\n")
        for n in sorted(solution.u):
            ux, uz = solution.u[n]
            f.write(f"{n},{ux!r},{uz!r}\n")
    with open(os.path.join(case_dir, "stresses.csv"), "w") as f:
        f.write("node_id,sigma_x,sigma_z,tau_xz,sigma_out_of_plane\n")
        for n in sorted(solution.stress):
            s = solution.stress[n]
            f.write(f"{n},{s[0]!r},{s[1]!r},{s[2]!r},{s[3]!r}\n")
    if solution.pressure:
        with open(os.path.join(case_dir, "contact_pressure.csv"), "w") as f:
            f.write("node_id,pressure\n")
            for n in sorted(solution.pressure):
                f.write(f"{n},{float(solution.pressure[n])!r}\n")
    with open(os.path.join(case_dir, "status.json"), "w") as f:
        json.dump({"converged": solution.converged, "iterations": solution.iterations,
                   "n_equations": 2 * len(solution.u), "reason": solution.reason,
                   "solver_version": version}, f)


def getfem_version():
    """The Debian package's version (GetFEM's Python interface has no version query)."""
    import subprocess
    try:
        out = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "python3-getfem"],
                             capture_output=True, text=True, check=True).stdout
        return "GetFEM " + out.strip()
    except (OSError, subprocess.CalledProcessError):
        return "GetFEM (version unknown)"


def main(argv):
    if len(argv) == 2 and argv[1] == "--version":
        print(getfem_version())
        return 0
    if len(argv) != 3:
        print("usage: getfem_case.py CASE_DIR OPTION | --version", file=sys.stderr)
        return 2
    case_dir, option = argv[1], argv[2]
    try:
        case = Case(case_dir)
        solution = solve(case, option)
    except CaseError as e:
        print(f"getfem adapter: {e}", file=sys.stderr)
        return 3
    if not solution.converged:
        solution.reason = f"GetFEM's Newton did not converge in {solution.iterations} iterations"
    write_results(case_dir, solution, getfem_version())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
