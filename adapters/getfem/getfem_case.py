#!/usr/bin/env python3
"""GetFEM (Debian python3-getfem 5.4.2) as an external code of contact-suite's solver protocol.

Solves one case directory (docs/solver-protocol.md): plane strain, linear elasticity of the
deformable body against the rigid target's analytic profile, with one of GetFEM's contact bricks
for a rigid obstacle, chosen by the option label:

  nodal_al     add_nodal_contact_with_rigid_obstacle_brick (nodal augmented Lagrangian,
               Alart-Curnier, non-symmetric; multipliers = nodal contact forces), r = E / h
  integral_al  add_integral_contact_with_rigid_obstacle_brick (integral augmented Lagrangian,
               option 1; the multiplier a contact stress on the boundary's Lagrange FEM), r = E/h
  penalty      add_penalized_contact_with_rigid_obstacle_brick, r = 50 E / h
  nitsche      add_Nitsche_contact_with_rigid_obstacle_brick, theta = 1, gamma0 = 50 E

Against a second meshed body (IF_p) the first three use GetFEM's bricks between non-matching
meshes (add_nodal_/add_integral_/add_penalized_contact_between_nonmatching_meshes_brick), the
contact surface's body the slave; Nitsche is not supported there (the case fails with why).
An initial overlap beyond the window of the integral and penalized bricks' projection fails the
case with why (check_projection) instead of their division by zero.

The case directory is read and the results written by the Python package contact_suite
(read_case, write_results); everything here is GetFEM. The porting notes (node order, the
vertical mode, nodal pressure from the methods) are in docs/solver-protocol.md, section 5.

Load control (S: a total load, the depth unknown) is one Newton solve with the depth as an
unknown (Problem.add_load_control).

Usage: getfem_case.py CASE_DIR OPTION     (writes the result files into CASE_DIR)
       getfem_case.py --version
"""
import subprocess
import sys

import numpy as np

import contact_suite as cs

OPTIONS = ("nodal_al", "integral_al", "penalty", "nitsche")
PENALTY_FKN = 50.0  # penalty stiffness r = FKN E / h (CalculiX's HARD contact: K = 50 E)
GAMMA0_FKN = 50.0  # Nitsche: gamma = gamma0 / h with gamma0 = FKN E
AL_FKN = 1.0  # augmentation parameter r = FKN E / h (GetFEM's guide: close to E)
CONTACT = 1  # the GetFEM region number of the contact surface
MAX_ITER = 100  # Newton iterations before GetFEM's solve stops
# GetFEM's default linear solver for a 2D model is SuperLU, whatever its size. On S(1/3) F Q4
# (524,000 equations) its first Newton iteration had not finished after 8 minutes at 3.4 GB;
# MUMPS (Debian's python3-getfem links the sequential MUMPS) solved the whole case, 11
# iterations, in 90 s at 2.3 GB.
LINEAR_SOLVER = "mumps"

# Our counter-clockwise order -> GetFEM's lexicographic QK order.
Q4_TO_GETFEM = (0, 1, 3, 2)
Q8_TO_GETFEM = (0, 4, 1, 7, 5, 3, 6, 2)


class CaseError(Exception):
    """A case this adapter cannot solve: the message is the reason."""

    exit_status = 3  # the adapter's refusal: not supported, or a case it cannot read


class GetfemFailure(CaseError):
    """GetFEM fails on a case the adapter supports (the exit status of GetFEM's own errors)."""

    exit_status = 1


def supported_bodies(case, option):
    """(the body whose surface makes contact, the meshed target's body or None) in plane strain,
    or CaseError: a rigid target has one deformable body, a meshed one two."""
    if case.analysis != "plane_strain":
        raise CaseError("not supported: axisymmetric analysis (the "
                        "r-weighted weak form is not written)")
    meshed = case.contact.target_kind == "meshed"
    bodies = case.deformable_bodies
    if len(bodies) != (2 if meshed else 1):
        raise CaseError(f"{len(bodies)} deformable bodies against a {case.contact.target_kind} "
                        "target; the adapter solves one against a rigid target or two in contact")
    if not meshed:
        return bodies[0], None
    if option == "nitsche":
        raise CaseError("not supported: Nitsche between two meshes (GetFEM 5.4 "
                        "has it only as its large-sliding raytracing brick, not driven here)")
    if case.load_control.kind == "total_load":
        raise CaseError("not supported: load control with a meshed target")
    owner = case.contact.contact_surface.split(".")[0]
    body = next((b for b in bodies if b.name == owner), None)
    if body is None:
        raise CaseError(f"the contact surface '{case.contact.contact_surface}' names no body")
    return body, next(b for b in bodies if b is not body)


def obstacle_expression(profile):
    """The signed distance (> 0 outside the rigid region) in GetFEM's language, valid on the
    deformable body's side of the profile (x, y are GetFEM's coordinates: our x, z)."""
    p = profile.parameters
    if profile.type == "plane":
        (px, pz), (nx, nz) = p["point"], p["normal"]
        return f"(x-({px!r}))*({nx!r})+(y-({pz!r}))*({nz!r})"
    if profile.type == "circle":
        (cx, cz), r = p["center"], p["radius"]
        return f"sqrt(sqr(x-({cx!r}))+sqr(y-({cz!r})))-({r!r})"
    (cx, cz), (dx, dz) = p["face_center"], p["direction"]
    h = f"((x-({cx!r}))*({dx!r})+(y-({cz!r}))*({dz!r}))"
    s = f"abs((x-({cx!r}))*({dz!r})-(y-({cz!r}))*({dx!r}))"
    if profile.type == "rounded_flat_punch":
        b, r_e = p["half_width_b"], p["edge_radius_re"]
        return f"sqrt(sqr(max({s}-({b!r}),0))+sqr({h}+({r_e!r})))-({r_e!r})"
    a = p["half_width_a"]
    return f"sqrt(sqr(max({s}-({a!r}),0))+sqr({h}))"


def coordinate_key(x, z):
    return (round(float(x), 12), round(float(z), 12))


class Discretization:
    """The body's mesh in GetFEM, its displacement FEM, integration, and our nodes' DOFs."""

    def __init__(self, gf, case, body):
        q8 = body.element == "Q8"
        self.gf, self.q8 = gf, q8
        self.mesh = gf.Mesh("empty", 2)
        gt = gf.GeoTrans("GT_Q2_INCOMPLETE(2)" if q8 else "GT_QK(2,1)")
        order = list(Q8_TO_GETFEM if q8 else Q4_TO_GETFEM)
        for e in body.elements:
            self.mesh.add_convex(gt, case.nodes[e[order]].T)
        self.mfu = gf.MeshFem(self.mesh, 2)
        self.mfu.set_fem(self.scalar_fem())
        self.mim = gf.MeshIm(self.mesh, gf.Integ(f"IM_GAUSS_PARALLELEPIPED(2,{6 if q8 else 4})"))
        self.nodes = np.unique(body.elements)
        self.dofs = self.node_dofs(case)

    def scalar_fem(self, discontinuous=False):
        if self.q8:
            name = "FEM_Q2_INCOMPLETE_DISCONTINUOUS(2)" if discontinuous else "FEM_Q2_INCOMPLETE(2)"
        else:
            name = "FEM_QK_DISCONTINUOUS(2,1)" if discontinuous else "FEM_QK(2,1)"
        return self.gf.Fem(name)

    def scalar_mesh_fem(self, discontinuous=False):
        mf = self.gf.MeshFem(self.mesh, 1)
        mf.set_fem(self.scalar_fem(discontinuous))
        return mf

    def node_dofs(self, case):
        """int array (n_nodes, 2): GetFEM's (u_x, u_z) DOFs of our nodes (-1: not the body's),
        matched by coordinates."""
        pts = self.mfu.basic_dof_nodes()
        index = {}
        for d in range(pts.shape[1]):
            index.setdefault(coordinate_key(*pts[:, d]), []).append(d)
        out = np.full((case.n_nodes, 2), -1, dtype=int)
        for n in self.nodes:
            dofs = index.get(coordinate_key(*case.nodes[n]))
            if dofs is None or len(dofs) != 2:
                raise CaseError(f"node {n + 1} at {tuple(case.nodes[n])} has no GetFEM DOFs")
            out[n] = dofs
        return out

    def set_region(self, case, edge_set, rnum):
        """GetFEM region `rnum`: the faces of the elements on `edge_set`."""
        pts = self.mesh.pts()
        pid = {coordinate_key(*pts[:, i]): i for i in range(pts.shape[1])}
        ids = [pid[coordinate_key(*case.nodes[n])] for n in np.unique(case.edge_sets[edge_set])]
        self.mesh.set_region(rnum, self.mesh.faces_from_pid(ids))


def add_contact(md, disc, case, option, E):
    """The option's contact brick on region CONTACT (E: the body's Young's modulus, the scale of
    the augmentation, penalty and Nitsche parameters)."""
    h = case.side_lengths(case.contact.contact_surface).min()  # the contact surface's smallest side
    obstacle = disc.scalar_mesh_fem()
    md.add_initialized_fem_data(
        "obstacle", obstacle, case.contact.profile.signed_distance(*obstacle.basic_dof_nodes()))
    if option == "nodal_al":
        md.add_variable("lambda_n", len(disc.mfu.basic_dof_on_region(CONTACT)) // 2)
        md.add_initialized_data("r", [AL_FKN * E / h])
        md.add_nodal_contact_with_rigid_obstacle_brick(
            disc.mim, "u", "lambda_n", "r", CONTACT, obstacle_expression(case.contact.profile), 1)
    elif option == "integral_al":
        md.add_filtered_fem_variable("lambda_n", disc.scalar_mesh_fem(), CONTACT)
        md.add_initialized_data("r", [AL_FKN * E / h])
        md.add_integral_contact_with_rigid_obstacle_brick(
            disc.mim, "u", "lambda_n", "obstacle", "r", CONTACT, 1)
    elif option == "penalty":
        md.add_initialized_data("r", [PENALTY_FKN * E / h])
        md.add_penalized_contact_with_rigid_obstacle_brick(disc.mim, "u", "obstacle", "r",
                                                           CONTACT)
    elif option == "nitsche":
        md.add_initialized_data("gamma0", GAMMA0_FKN * E)
        # Without a friction coefficient GetFEM 5.4 builds a call of the friction projection
        # with the wrong arguments ("Wrong number or wrong size of arguments ... Coulomb_
        # friction_coupled_projection"): a zero coefficient is frictionless.
        md.add_initialized_data("friction_coeff", 0.0)
        md.add_Nitsche_contact_with_rigid_obstacle_brick(
            disc.mim, "u", md.Neumann_term("u", CONTACT), "obstacle", "gamma0", CONTACT, 1.0,
            "friction_coeff")
    else:
        raise CaseError(f"unknown option '{option}' (known: {', '.join(OPTIONS)})")


def check_projection(gf, disc, target, case):
    """GetfemFailure unless the projected FEM of the target's displacement that GetFEM 5.4's
    integral and penalized bricks between non-matching meshes build (getfem_contact_and_
    friction_integral.cc: new_projected_fem(mf_u2, mim, rg2, rg1) on all the slave's convexes)
    has DOFs. Its projection accepts a slave integration point only nearer to the target surface
    than 0.05 x the target convex's radius estimate (getfem_projected_fem.cc, fixed, "FIXME");
    with none accepted it has no DOF and the brick's assembly divides 0 by 0 (SIGFPE in
    slice_vector_on_basic_dof_of_element). So on IF_p F: its bodies overlap by 0.001 b in the
    reference geometry, beyond F's window (at most 8.7e-4 b) but within C's and M's."""
    projected = gf.MeshFem(disc.mesh, 2)
    projected.set_fem(gf.Fem("projected_fem", target.mfu, disc.mim, CONTACT, CONTACT))
    if projected.nbdof() > 0:
        return
    points = disc.mim.im_nodes(disc.mesh.region(CONTACT))[:2].T
    distance, inside = surface_distance(case, case.contact.target_surface, points)
    window = 0.05 * float(np.max(target.mesh.convex_radius(target.mesh.region(CONTACT)[0])))
    what = "overlap" if inside.all() else "gap" if not inside.any() else "overlap or gap"
    d = distance.min()
    relation = (f"the initial {what} ({d:.1e}) exceeds its fixed window of 5 % of the target "
                f"element size (at most {window:.1e} here)" if d >= window else
                f"the initial {what} is at least {d:.1e} and its fixed window of 5 % of the "
                f"target element size at most {window:.1e} here")
    raise GetfemFailure(f"GetFEM 5.4's projected FEM accepts no integration point: {relation}; "
                        "its brick would divide by zero")


def surface_distance(case, edge_set, points):
    """(distance, inside): each point's (m, 2) distance to the surface `edge_set` (its sides
    straight, or quadratic through their middle node, sampled finely) and whether it lies inside
    the body of its nearest side (behind that side, seen from outside its element)."""
    sides = case.edge_sets[edge_set]
    centre = {}  # a side's end nodes -> the centre of its element's corners
    for body in case.deformable_bodies:
        for e in body.elements:
            c = e[:4]
            for k in range(4):
                centre[frozenset((int(c[k]), int(c[(k + 1) % 4])))] = case.nodes[c].mean(axis=0)
    s = np.linspace(0.0, 1.0, 2 if sides.shape[1] == 2 else 33)
    shape = (np.stack([1 - s, s]) if sides.shape[1] == 2 else
             np.stack([(1 - s) * (1 - 2 * s), s * (2 * s - 1), 4 * s * (1 - s)]))
    rows = np.arange(len(points))
    best = np.full(len(points), np.inf)
    inside = np.zeros(len(points), dtype=bool)
    for side in sides:
        curve = shape.T @ case.nodes[side]  # (len(s), 2)
        a, ab = curve[:-1], np.diff(curve, axis=0)
        t = np.clip(np.einsum("pkj,kj->pk", points[:, None, :] - a, ab)
                    / np.einsum("kj,kj->k", ab, ab), 0.0, 1.0)
        near = a + t[..., None] * ab  # (m, segments, 2): the nearest point of each segment
        dist = np.linalg.norm(points[:, None, :] - near, axis=2)
        k = dist.argmin(axis=1)
        nearest = near[rows, k]
        closer = dist[rows, k] < best
        best[closer] = dist[rows, k][closer]
        outward = np.stack([ab[k, 1], -ab[k, 0]], axis=1)
        c = centre.get(frozenset((int(side[0]), int(side[1]))))
        if c is not None:
            outward *= np.sign(np.einsum("pj,pj->p", outward, nearest - c))[:, None]
            inside[closer] = (np.einsum("pj,pj->p", points - nearest, outward) < 0)[closer]
        else:
            inside[closer] = False
    return best, inside


def add_meshed_contact(md, disc, target, case, option, E):
    """The option's brick between the body's region CONTACT and the target body's (small
    sliding, non-matching meshes; the body's surface is the slave): nodal or integral augmented
    Lagrangian, or penalty, with the parameters of the rigid-obstacle bricks. The integral and
    penalized bricks are added only if GetFEM's projection accepts the contact
    (check_projection)."""
    h = case.side_lengths(case.contact.contact_surface).min()
    if option in ("integral_al", "penalty"):
        check_projection(disc.gf, disc, target, case)
    if option == "nodal_al":
        md.add_initialized_data("r", [AL_FKN * E / h])
        md.add_nodal_contact_between_nonmatching_meshes_brick(
            disc.mim, target.mim, "u", "u_t", "lambda_n", "r", CONTACT, CONTACT)
    elif option == "integral_al":
        md.add_filtered_fem_variable("lambda_n", disc.scalar_mesh_fem(), CONTACT)
        md.add_initialized_data("r", [AL_FKN * E / h])
        md.add_integral_contact_between_nonmatching_meshes_brick(
            disc.mim, "u", "u_t", "lambda_n", "r", CONTACT, CONTACT, 1)
    elif option == "penalty":
        md.add_initialized_data("r", [PENALTY_FKN * E / h])
        md.add_penalized_contact_between_nonmatching_meshes_brick(
            disc.mim, "u", "u_t", "r", CONTACT, CONTACT, 1)
    else:
        raise CaseError(f"unknown option '{option}' (known: {', '.join(OPTIONS)})")


class Problem:
    """The GetFEM model of the case: elasticity, loads, prescribed displacements as rows of
    add_constraint_with_multipliers (their multipliers are the reactions), contact.

    Under load control (S: a given total load, the depth delta unknown) the depth is one more
    unknown of the same Newton solve: the load-controlled DOFs are tied to a scalar w = -delta
    by the rows B_c u - w e = 0 (explicit matrices, multipliers mult_c, their sum the reaction
    of the set), and w's own row, -e^T mult_c = -P, states that the set carries the total load
    P. One Newton solve replaces a secant search over delta (a Newton solve per trial depth)."""

    def __init__(self, gf, case, bodies, option):
        body, target_body = bodies
        self.case, self.E, self.disc = case, body.E, Discretization(gf, case, body)
        self.md = gf.Model("real")
        self.disc.set_region(case, case.contact.contact_surface, CONTACT)
        self.add_body(gf, "u", "", self.disc, body)
        self.target = None
        if target_body is not None:
            self.target = Discretization(gf, case, target_body)
            self.target.set_region(case, case.contact.target_surface, CONTACT)
            self.add_body(gf, "u_t", "_t", self.target, target_body)
        self.load_controlled = case.load_control.kind == "total_load"
        if self.load_controlled:
            self.add_load_control(gf, self.disc.dofs.ravel()[case.load_controlled_dofs()])
        if self.target is None:
            add_contact(self.md, self.disc, case, option, body.E)
        else:
            add_meshed_contact(self.md, self.disc, self.target, case, option, body.E)

    def add_body(self, gf, variable, suffix, disc, body):
        """The body's displacement `variable`, its elasticity (data lambda<suffix>,
        mu<suffix>), its nodal forces and its prescribed displacements."""
        md, case, E, nu = self.md, self.case, body.E, body.nu
        md.add_fem_variable(variable, disc.mfu)
        md.add_initialized_data("lambda" + suffix, [E * nu / ((1 + nu) * (1 - 2 * nu))])
        md.add_initialized_data("mu" + suffix, [E / (2 * (1 + nu))])
        md.add_isotropic_linearized_elasticity_brick(disc.mim, variable, "lambda" + suffix,
                                                     "mu" + suffix)
        force = np.zeros(disc.mfu.nbdof())
        on_body = disc.dofs[:, 0] >= 0
        np.add.at(force, disc.dofs[on_body].ravel(), case.nodal_forces[on_body].ravel())
        md.add_explicit_rhs(variable, force)
        given, values = case.prescribed()
        given_dofs = disc.dofs.ravel()[given]
        mine = given_dofs >= 0
        md.add_variable("mult_bc" + suffix, int(np.sum(mine)))
        md.add_constraint_with_multipliers(variable, "mult_bc" + suffix,
                                           self.rows(gf, given_dofs[mine], disc), values[mine])

    def rows(self, gf, dofs, disc=None):
        """The Spmat with a row per DOF of `dofs` (1 in the DOF's column) of `disc`'s FEM (the
        contact body's by default)."""
        B = gf.Spmat("empty", len(dofs), (disc or self.disc).mfu.nbdof())
        for i, d in enumerate(dofs):
            B[i, int(d)] = 1.0
        return B

    def add_load_control(self, gf, controlled):
        """The depth w = -delta as an unknown, tied to the load-controlled DOFs, and the row
        stating that they carry the total load (see the class)."""
        md, n = self.md, len(controlled)
        md.add_variable("mult_c", n)
        md.add_variable("w", 1)
        md.add_explicit_matrix("mult_c", "u", self.rows(gf, controlled), 1)
        tie = gf.Spmat("empty", n, 1)
        for i in range(n):
            tie[i, 0] = -1.0
        md.add_explicit_matrix("mult_c", "w", tie, 1)
        md.add_explicit_rhs("w", [-self.case.load_control.total_load])

    def solve(self):
        """Newton from the vertical mode's start (against a rigid target; two meshed bodies start
        at rest); (iterations, converged)."""
        delta = self.case.load_control.depth_guess if self.load_controlled else 0.0
        if self.target is None:
            self.md.set_variable("u", self.start_u(delta))
        if self.load_controlled:
            self.md.set_variable("w", [-delta])
        out = self.md.solve("max_res", 1e-9, "max_iter", MAX_ITER, "lsearch", "simplest",
                            "lsolver", LINEAR_SOLVER)
        nit = int(out[0]) if np.ndim(out) else int(out)
        converged = bool(out[1]) if np.ndim(out) and len(out) > 1 else nit < MAX_ITER
        return nit, converged

    def start_u(self, delta):
        """The vertical mode (docs/solver-protocol.md): a rigid translation of the block onto
        the obstacle by a small fraction of its load's elastic displacement, plus the depth."""
        u = np.zeros(self.disc.mfu.nbdof())
        u[1::2] = -(self.case.p / self.E) * self.case.length_unit * 1e-3 - delta
        return u


def nodal_stresses(problem):
    """GetFEM's own nodal stresses, as its users read them: Hooke's stress interpolated
    (Model.interpolation) on a discontinuous FEM of the displacement's degree, i.e. evaluated at
    each element's nodes, then averaged over the elements at each node; (nodes, array (k, 4) of
    sigma_x, sigma_z, tau_xz, out of plane). On a parallelogram Q4 this equals the element-wise
    L2 projection (every stress component is then in the element's Q1 space); on a distorted
    element the two differ (by 0.4 % of the peak on S(1/3) C), and the L2 projection
    (Model.local_projection) costs about 20 times more."""
    disc, md, case = problem.disc, problem.md, problem.case
    mfs = disc.scalar_mesh_fem(discontinuous=True)
    exprs = ("lambda*Trace(Grad_u)+2*mu*Grad_u(1,1)", "lambda*Trace(Grad_u)+2*mu*Grad_u(2,2)",
             "mu*(Grad_u(1,2)+Grad_u(2,1))", "lambda*Trace(Grad_u)")
    values = np.array([md.interpolation(e, mfs) for e in exprs]).T
    pts = mfs.basic_dof_nodes()
    sums, counts = {}, {}
    for d in range(pts.shape[1]):
        key = coordinate_key(*pts[:, d])
        sums[key] = sums.get(key, 0.0) + values[d]
        counts[key] = counts.get(key, 0) + 1
    keys = [coordinate_key(*case.nodes[n]) for n in disc.nodes]
    return disc.nodes, np.array([sums[k] / counts[k] for k in keys])


def tributary_lengths(case, edge_set):
    """{node: its share of the surface's length} (lumped: half of each side; Q8 sides by
    Simpson's weights 1/6 at the ends, 2/3 in the middle)."""
    sides = case.edge_sets[edge_set]
    lengths = case.side_lengths(edge_set)
    weights = [1 / 6, 1 / 6, 2 / 3] if sides.shape[1] == 3 else [0.5, 0.5]
    out = {}
    for side, length in zip(sides, lengths):
        for n, w in zip(side, weights):
            out[int(n)] = out.get(int(n), 0.0) + w * length
    return out


def contact_pressure(problem, option):
    """The code's own nodal contact pressure (> 0 in compression) where it gives one:
    (nodes, pressures), or None."""
    disc, md, case = problem.disc, problem.md, problem.case
    surface = case.contact.contact_surface
    if problem.target is not None and option != "nodal_al":
        return None  # between two meshes: derived from the forces (docs/solver-protocol.md)
    if option == "nodal_al":
        # One multiplier per node of the region, in the order of the region's z DOFs: the
        # nodal contact force (<= 0 in compression), over the node's tributary length.
        forces = md.variable("lambda_n")
        z_dofs = [d for d in disc.mfu.basic_dof_on_region(CONTACT) if d % 2 == 1]
        node_of = {int(dz): n for n, (_, dz) in enumerate(disc.dofs) if dz >= 0}
        lengths = tributary_lengths(case, surface)
        nodes = np.array([node_of[d] for d in z_dofs])
        return nodes, np.array([-forces[k] / lengths[n] for k, n in enumerate(nodes)])
    if option == "integral_al":
        return integral_pressure(problem)
    return law_pressure(problem, option)


def law_pressure(problem, option):
    """The traction the penalty or Nitsche brick imposes, at each node of the contact surface
    (> 0 in compression); (nodes, pressures). With g = obstacle + Grad_obstacle.u the gap (the
    obstacle's signed distance, linearized in u as the bricks do) and n its normal:

      penalty:  p = r max(0, -g)
      Nitsche:  p = max(0, -n.sigma(u).n - (gamma0 / element_size) g)

    each evaluated (Model.interpolation) at an element's nodes on the surface and averaged over
    the elements at a node, as nodal_stresses does. For Nitsche's method the residual's nodal
    forces are not this traction: they also hold its consistency terms, theta sigma(v).n
    (docs/solver-protocol.md, section 5)."""
    disc, md, case = problem.disc, problem.md, problem.case
    gap = "(obstacle + Grad_obstacle.u)"
    if option == "penalty":
        expr = f"r*pos_part(-{gap})"
    else:
        n = "Normalized(Grad_obstacle)"
        sigma = "(lambda*Trace(Grad_u)*Id(2) + mu*(Grad_u + Grad_u'))"
        expr = f"pos_part(-({n}.({sigma}*{n})) - (gamma0/element_size)*{gap})"
    mfs = disc.scalar_mesh_fem(discontinuous=True)
    values = md.interpolation(expr, mfs, CONTACT)
    pts = mfs.basic_dof_nodes()
    on_surface = mfs.basic_dof_on_region(CONTACT)
    sums, counts = {}, {}
    for d in on_surface:
        key = coordinate_key(*pts[:, d])
        sums[key] = sums.get(key, 0.0) + values[d]
        counts[key] = counts.get(key, 0) + 1
    nodes = np.array([n for n in np.unique(case.edge_sets[case.contact.contact_surface])
                      if coordinate_key(*case.nodes[n]) in sums])
    keys = [coordinate_key(*case.nodes[n]) for n in nodes]
    return nodes, np.array([sums[k] / counts[k] for k in keys])


def integral_pressure(problem):
    """The integral brick's nodal pressure: at each node of the contact surface, the multiplier
    lambda (> 0 in compression) where the node is in contact by the brick's own test,
    lambda - r g > 0 with g the node's gap in the deformed configuration, and 0 elsewhere;
    (nodes, pressures).

    Two traps: (1) a filtered variable holds only the DOFs of its FEM on the region, in their
    order: entry k is DOF basic_dof_on_region(region)[k] of the whole FEM, not DOF k; (2) the
    brick enforces the contact law in the integral sense, so the multiplier's nodal values
    oscillate about zero past the contact edge (alternating, decaying by about 4 per node), and
    the first non-zero value past the edge would be read as the contact half-width."""
    disc, md, case = problem.disc, problem.md, problem.case
    lam = md.variable("lambda_n")
    mfl = md.mesh_fem_of_variable("lambda_n")
    region_dofs = mfl.basic_dof_on_region(CONTACT)
    if len(region_dofs) != len(lam):
        raise CaseError(f"the multiplier has {len(lam)} values for {len(region_dofs)} DOFs")
    pts = mfl.basic_dof_nodes(region_dofs)
    at = {coordinate_key(*pts[:, k]): -lam[k] for k in range(len(lam))}
    nodes = np.array([n for n in np.unique(case.edge_sets[case.contact.contact_surface])
                      if coordinate_key(*case.nodes[n]) in at])
    multiplier = np.array([at[coordinate_key(*case.nodes[n])] for n in nodes])
    deformed = case.nodes[nodes] + md.variable("u")[disc.dofs[nodes]]
    gap = case.contact.profile.signed_distance(deformed[:, 0], deformed[:, 1])
    r = float(md.variable("r")[0])
    return nodes, np.where(multiplier - r * gap > 0.0, np.maximum(multiplier, 0.0), 0.0)


def not_converged_reason(iterations):
    """Why the case did not converge: GetFEM's Newton reports 0 iterations when it gives up (a
    failed line search or a diverging residual), else its iteration cap was reached."""
    if iterations == 0:
        return "GetFEM's Newton gave up (line search failed or the residual diverged)"
    return f"GetFEM's Newton did not converge in {iterations} iterations (its cap: {MAX_ITER})"


def solve_and_write(case, option, version):
    import getfem as gf

    gf.util_trace_level(0)
    gf.util_warning_level(0)
    if option not in OPTIONS:
        raise CaseError(f"unknown option '{option}' (known: {', '.join(OPTIONS)})")
    problem = Problem(gf, case, supported_bodies(case, option), option)
    iterations, converged = problem.solve()
    disc, target = problem.disc, problem.target
    nodes = disc.nodes if target is None else np.concatenate([disc.nodes, target.nodes])
    u = problem.md.variable("u")[disc.dofs[disc.nodes]]
    if target is not None:
        u = np.concatenate([u, problem.md.variable("u_t")[target.dofs[target.nodes]]])
    stress_nodes, stress = nodal_stresses(problem)
    pressure = contact_pressure(problem, option)
    cs.write_results(
        case.path, nodes=nodes, displacement=u, stress=stress, stress_nodes=stress_nodes,
        contact_pressure=None if pressure is None else pressure[1],
        pressure_nodes=None if pressure is None else pressure[0], converged=converged,
        iterations=iterations, n_equations=2 * len(nodes),
        reason="" if converged else not_converged_reason(iterations),
        solver_version=version, case=case)


def getfem_version():
    """The Debian package's version (GetFEM's Python interface has no version query)."""
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
    try:
        solve_and_write(cs.read_case(argv[1]), argv[2], getfem_version())
    except (CaseError, ValueError) as e:
        print(f"getfem adapter: {e}", file=sys.stderr)
        return getattr(e, "exit_status", 3)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
