"""The reader of the solver protocol's case directory (docs/solver-protocol.md, section 2).

The engine writes each case for an external code as a directory holding

    mesh.msh    Gmsh MSH 4.1 ASCII: the nodes (tag = node index + 1, coordinates (x, z, 0)), the
                bodies' quadrilaterals, every edge set as line elements and every node set as
                point elements, each set a physical group of its name;
    case.json   the analysis, materials, boundary conditions, loads, contact pair (with a rigid
                target's analytic profile), load control and what is sampled.

read_case() turns both into NumPy arrays. Conventions, the same throughout:

- a node is its **index** (0-based, = the node id of mesh.msh and the result files - 1); an
  array of nodes is an int array of indices into `Case.nodes`;
- coordinates (x, z): x along the surface (r for axisymmetric, the axis at x = 0), z into the
  indented body (the rigid target lies at z < 0);
- a degree of freedom is 2 n + c with c = 0 for u_x, 1 for u_z;
- units are the case's own consistent units: lengths as in mesh.msh, stresses and E in the
  units of p (`Case.p`), forces per unit thickness (plane strain) or per radian
  (axisymmetric: `Case.force_basis`); tension positive, contact pressure > 0 in compression.

Anything the files do not hold as documented raises ValueError naming the file and the field.
"""
import json
import math
import os
from dataclasses import dataclass, field

import numpy as np

FORMAT = "contact-suite case"
FORMAT_VERSION = 1

# Gmsh element types: number of nodes.
_QUAD_TYPES = {3: ("Q4", 4), 16: ("Q8", 8)}
_LINE_TYPES = {1: 2, 8: 3}
_POINT_TYPE = 15


class _Missing(ValueError):
    pass


@dataclass(frozen=True, eq=False)
class Body:
    """One body of the mesh (a physical group of dimension 2).

    name      the group's name, e.g. "block", "indenter"
    role      "deformable", or "fixed_not_in_contact" (the mesh of a rigid target: it takes no
              part, and needs no displacement)
    E, nu     Young's modulus [units of p] and Poisson's ratio [-], linear isotropic
    element   "Q4" or "Q8"
    elements  int array (m, 4) or (m, 8): node indices in our order, which is Gmsh's: corners
              counter-clockwise, then (Q8) the mid-side nodes of sides 0-1, 1-2, 2-3, 3-0
    element_ids  int array (m,): the elements' ids in mesh.msh (element index + 1)
    """
    name: str
    role: str
    E: float
    nu: float
    element: str
    elements: np.ndarray
    element_ids: np.ndarray

    @property
    def deformable(self):
        return self.role == "deformable"


@dataclass(frozen=True, eq=False)
class Constraint:
    """A prescribed displacement component on a set of nodes.

    set, set_kind    the set's name and kind ("node_set" or "edge_set": then its nodes)
    component        "x" or "z"
    nodes            int array (k,): node indices
    values           float array (k,): u_component at each node [length]; None when
                     load_controlled
    load_controlled  True: u_z = -delta at every node, delta the unknown of the load control
                     (Case.load_control)
    """
    set: str
    set_kind: str
    component: str
    nodes: np.ndarray
    values: object
    load_controlled: bool = False

    @property
    def dofs(self):
        """The degrees of freedom 2 n + c (c = 0: x, 1: z) of the nodes."""
        return 2 * self.nodes + (0 if self.component == "x" else 1)


@dataclass(frozen=True, eq=False)
class RigidProfile:
    """A rigid target's analytic profile; signed_distance() is > 0 outside the rigid region.

    type        "plane" (point, normal), "circle" (center, radius), "rounded_flat_punch"
                (face_center, direction d into the body, half_width_b, edge_radius_re) or
                "sharp_flat_punch" (face_center, direction, half_width_a)
    parameters  those parameters as case.json gives them: points and directions as (x, z)
                tuples, lengths as floats
    formula     case.json's statement of g(x)
    """
    type: str
    parameters: dict
    formula: str = ""

    def signed_distance(self, x, z):
        """g(x, z) [length] at points (NumPy arrays broadcast together, or floats): > 0 outside
        the rigid region, 0 on its boundary (docs/solver-protocol.md, "Rigid profiles")."""
        x, z = np.asarray(x, dtype=float), np.asarray(z, dtype=float)
        p = self.parameters
        if self.type == "plane":
            (px, pz), (nx, nz) = p["point"], p["normal"]
            return (x - px) * nx + (z - pz) * nz
        if self.type == "circle":
            (cx, cz), r = p["center"], p["radius"]
            return np.hypot(x - cx, z - cz) - r
        (cx, cz), (dx, dz) = p["face_center"], p["direction"]
        h = (x - cx) * dx + (z - cz) * dz  # along d, into the body
        s = np.abs((x - cx) * dz - (z - cz) * dx)  # across, from the punch's axis
        if self.type == "rounded_flat_punch":
            b, r_e = p["half_width_b"], p["edge_radius_re"]
            rounded = np.hypot(s - b, h + r_e) - r_e
            return np.where(s <= b, h, np.where(h >= -r_e, rounded, s - b - r_e))
        a = p["half_width_a"]
        return np.where(s <= a, h, np.where(h >= 0.0, np.hypot(s - a, h), s - a))


@dataclass(frozen=True, eq=False)
class ContactPair:
    """The contact pair: `contact_surface` (an edge set of the deformable body) against a target:
    target_kind "rigid" with `profile`, or "meshed" with `target_surface` (an edge set).
    gap_normal: "target" or "contact_surface"; frictionless: bool."""
    contact_surface: str
    target_kind: str
    profile: object = None
    target_surface: str = ""
    gap_normal: str = "target"
    frictionless: bool = True


@dataclass(frozen=True, eq=False)
class LoadControl:
    """How the problem is loaded.

    kind          "given_loads" (every load and displacement given) or "total_load" (S with a
                  rigid punch: the depth delta is unknown)
    total_load    the z reaction the reaction set must carry [force per unit thickness, half
                  model]; NaN for given_loads
    reaction_set  the set whose nodes all have u_z = -delta; nodes: their indices
    depth_guess   a first guess of delta for its scale [length]; NaN for given_loads
    """
    kind: str
    total_load: float = math.nan
    component: str = "z"
    reaction_set: str = ""
    nodes: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    depth_guess: float = math.nan


@dataclass(frozen=True, eq=False)
class Case:
    """One case directory, read (see the module's conventions).

    path            the directory
    case_id, problem, mesh_level   e.g. "P_p/C/Q4/LMP/ns/rigid/@mycode:exact", "P_p", "C"
    option          the option label the code is asked to run ("" for none)
    analysis        "plane_strain" or "axisymmetric"; force_basis "per_unit_thickness" or
                    "per_radian"
    element         "Q4" or "Q8"
    nodes           float array (n, 2): (x, z) of every node [length]
    bodies          [Body]: elements and materials
    node_sets       {name: int array}: every node set, and every edge set's nodes under its name
                    (mesh.msh writes a node set equal to its edge set's nodes only once)
    edge_sets       {name: int array (k, 2) or (k, 3)}: sides as node indices, both ends then
                    (Q8) the middle
    constraints     [Constraint]: the prescribed displacements, in case.json's order
    nodal_forces    float array (n, 2): the consistent nodal forces (f_x, f_z) of the
                    problem's tractions and pressures, at free DOFs [force]
    contact         ContactPair (with the rigid profile)
    load_control    LoadControl
    p, length_unit, contact_half_width_a   the normalizing pressure [stress], the length unit
                    (a; b for S) [length] and the exact contact half-width [length]
    sampled_surface, sampled_quantities   what is graded: the surface's name and per quantity
                    {quantity, component, rule, exact, study_exact} (exact: float, inf when
                    singular)
    result_files    {"displacements": "displacements.csv", ...}: the names to write
    json            case.json as a dict
    """
    path: str
    case_id: str
    problem: str
    mesh_level: str
    option: str
    analysis: str
    force_basis: str
    element: str
    nodes: np.ndarray
    bodies: list
    node_sets: dict
    edge_sets: dict
    constraints: list
    nodal_forces: np.ndarray
    contact: ContactPair
    load_control: LoadControl
    p: float
    length_unit: float
    contact_half_width_a: float
    sampled_surface: str
    sampled_quantities: list
    result_files: dict
    json: dict

    @property
    def n_nodes(self):
        return len(self.nodes)

    def body(self, name):
        """The body called `name` (ValueError if none)."""
        for b in self.bodies:
            if b.name == name:
                return b
        raise ValueError(f"case {self.case_id}: no body '{name}'")

    @property
    def deformable_bodies(self):
        return [b for b in self.bodies if b.deformable]

    @property
    def deformable_nodes(self):
        """int array: the sorted indices of every node of a deformable body (those whose
        displacement the results must hold)."""
        parts = [b.elements.ravel() for b in self.deformable_bodies]
        return np.unique(np.concatenate(parts)) if parts else np.zeros(0, dtype=int)

    def prescribed(self):
        """(dofs, values): every given prescribed displacement (not the load-controlled ones) as
        int and float arrays; a DOF prescribed twice keeps its last value, as in case.json."""
        out = {}
        for c in self.constraints:
            if not c.load_controlled:
                out.update(zip(c.dofs.tolist(), c.values.tolist()))
        dofs = np.array(sorted(out), dtype=int)
        return dofs, np.array([out[d] for d in dofs.tolist()], dtype=float)

    def load_controlled_dofs(self):
        """int array: the DOFs whose value is -delta under load control (empty otherwise)."""
        parts = [c.dofs for c in self.constraints if c.load_controlled]
        return np.unique(np.concatenate(parts)) if parts else np.zeros(0, dtype=int)

    def side_lengths(self, edge_set):
        """float array (k,): the straight length of every side of `edge_set` (end to end)."""
        sides = self.edge_sets[edge_set]
        d = self.nodes[sides[:, 1]] - self.nodes[sides[:, 0]]
        return np.hypot(d[:, 0], d[:, 1])


# ---- mesh.msh -------------------------------------------------------------------------------

def _sections(text, name):
    """The lines of every $name ... $Endname section of an MSH file."""
    lines = text.split("\n")
    begin, end = "$" + name, "$End" + name
    try:
        start = lines.index(begin)
        stop = lines.index(end, start)
    except ValueError:
        raise _Missing(f"no {begin} section") from None
    return [ln.strip() for ln in lines[start + 1:stop]]


def _physical_names(text):
    rows = _sections(text, "PhysicalNames")
    out = {}
    for row in rows[1:1 + int(rows[0])]:
        dim, tag, name = row.split(" ", 2)
        out[(int(dim), int(tag))] = name.strip('"')
    return out


def _entity_groups(text):
    """(dim, entity tag) -> physical tags, from $Entities."""
    rows = _sections(text, "Entities")
    counts = [int(v) for v in rows[0].split()]
    out = {}
    at = 1
    for dim, count in enumerate(counts):
        for _ in range(count):
            v = rows[at].split()
            at += 1
            first = 4 if dim == 0 else 7  # a point: tag x y z; else tag and a bounding box
            n_phys = int(v[first])
            out[(dim, int(v[0]))] = [int(t) for t in v[first + 1:first + 1 + n_phys]]
    return out


def _read_nodes(text):
    rows = _sections(text, "Nodes")
    n_blocks, n_nodes = (int(v) for v in rows[0].split()[:2])
    tags, coords = [], []
    at = 1
    for _ in range(n_blocks):
        count = int(rows[at].split()[3])
        tags += [int(t) for t in rows[at + 1:at + 1 + count]]
        coords += [[float(v) for v in r.split()[:2]] for r in rows[at + 1 + count:at + 1 + 2 * count]]
        at += 1 + 2 * count
    if len(tags) != n_nodes or sorted(tags) != list(range(1, n_nodes + 1)):
        raise _Missing(f"$Nodes: the tags are not 1..{n_nodes}")
    nodes = np.zeros((n_nodes, 2))
    nodes[np.array(tags) - 1] = coords
    return nodes


def _read_elements(text, groups, names):
    """{(dim, name): [(gmsh type, [rows of ints])]} from $Elements."""
    rows = _sections(text, "Elements")
    n_blocks = int(rows[0].split()[0])
    out = {}
    at = 1
    for _ in range(n_blocks):
        dim, entity, etype, count = (int(v) for v in rows[at].split())
        block = [[int(v) for v in r.split()] for r in rows[at + 1:at + 1 + count]]
        at += 1 + count
        for phys in groups.get((dim, entity), []):
            name = names.get((dim, phys))
            if name is None:
                raise _Missing(f"physical group ({dim}, {phys}) has no name")
            out.setdefault((dim, name), []).append((etype, block))
    return out


def _mesh_sets(elements, n_nodes):
    """Quadrilateral blocks by body (element id, then node indices), edge sets, node sets from
    the element groups; a node tag outside 1..n_nodes is refused naming its group."""
    quads, edge_sets, node_sets = {}, {}, {}
    for (dim, name), blocks in elements.items():
        rows = np.array([r for _, block in blocks for r in block], dtype=int)
        types = {t for t, _ in blocks}
        where = f"$Elements: group '{name}'"
        if dim == 2:
            if len(types) != 1 or next(iter(types)) not in _QUAD_TYPES:
                raise _Missing(f"body '{name}': element types {sorted(types)} are not one of "
                               "3 (Q4) or 16 (Q8)")
            nodes = _node_ids(rows[:, 1:], n_nodes, where)
            quads[name] = (_QUAD_TYPES[next(iter(types))][0], rows[:, 0], nodes)
        elif dim == 1:
            if len(types) != 1 or next(iter(types)) not in _LINE_TYPES:
                raise _Missing(f"edge set '{name}': element types {sorted(types)} are not 1 or 8")
            edge_sets[name] = _node_ids(rows[:, 1:], n_nodes, where)
        elif dim == 0:
            node_sets[name.removesuffix(":nodes")] = _node_ids(rows[:, 1], n_nodes, where)
    for name, sides in edge_sets.items():
        node_sets.setdefault(name, np.unique(sides))
    return quads, edge_sets, node_sets


# ---- case.json ------------------------------------------------------------------------------

def _profile(j):
    kind = j["type"]
    if kind not in ("plane", "circle", "rounded_flat_punch", "sharp_flat_punch"):
        raise _Missing(f"contact_pair.target.profile.type '{kind}' is not known")
    params = {k: (tuple(v) if isinstance(v, list) else v)
              for k, v in j.items() if k not in ("type", "signed_distance")}
    return RigidProfile(kind, params, j.get("signed_distance", ""))


def _contact(j):
    target = j["target"]
    kind = target["kind"]
    if kind == "rigid":
        return ContactPair(j["contact_surface"], kind, profile=_profile(target["profile"]),
                           gap_normal=j["gap_normal"], frictionless=j["frictionless"])
    if kind == "meshed":
        return ContactPair(j["contact_surface"], kind, target_surface=target["surface"],
                           gap_normal=j["gap_normal"], frictionless=j["frictionless"])
    raise _Missing(f"contact_pair.target.kind '{kind}' is not rigid or meshed")


def _node_ids(ids, n_nodes, where):
    """0-based node indices of node ids (1..n_nodes) of case.json or mesh.msh, or _Missing
    naming `where`: an id of 0 or below would index from the end of a NumPy array."""
    ids = np.asarray(ids, dtype=int)
    bad = ids[(ids < 1) | (ids > n_nodes)]
    if bad.size:
        raise _Missing(f"{where}: node id {bad[0]} is not in 1..{n_nodes}")
    return ids - 1


def _constraint(j, node_sets, edge_sets, n_nodes):
    name, kind = j["set"], j["set_kind"]
    if kind == "edge_set":
        nodes = np.unique(edge_sets[name])
    elif kind == "node_set":
        nodes = node_sets[name]
    else:
        raise _Missing(f"boundary_conditions: set_kind '{kind}'")
    if j["component"] not in ("x", "z"):
        raise _Missing(f"boundary_conditions: component '{j['component']}' is not x or z")
    if j.get("load_controlled"):
        return Constraint(name, kind, j["component"], nodes, None, True)
    if "values" in j:
        pairs = j["values"]
        nodes = _node_ids([n for n, _ in pairs], n_nodes, "boundary_conditions: values")
        values = np.array([v for _, v in pairs], dtype=float)
    else:
        values = np.full(len(nodes), float(j["value"]))
    return Constraint(name, kind, j["component"], nodes, values)


def _load_control(j, constraints):
    if j["kind"] == "given_loads":
        return LoadControl("given_loads")
    if j["kind"] != "total_load":
        raise _Missing(f"load_control.kind '{j['kind']}' is not given_loads or total_load")
    controlled = [c.nodes for c in constraints if c.load_controlled]
    nodes = np.unique(np.concatenate(controlled)) if controlled else np.zeros(0, dtype=int)
    return LoadControl("total_load", float(j["total_load"]), j["component"], j["reaction_set"],
                       nodes, float(j["depth_guess"]))


def _float(v):
    """A number of case.json; null (how JSON writes a quantity that does not apply) is NaN."""
    return math.nan if v is None else float(v)


def _nodal_forces(j, n_nodes):
    out = np.zeros((n_nodes, 2))
    for n, fx, fz in j["nodal_forces"]:
        out[_node_ids([n], n_nodes, "loads.nodal_forces")[0]] += (fx, fz)
    return out


def _sampled(j):
    out = []
    for q in j["quantities"]:
        q = dict(q)
        q["exact"] = math.inf if q["exact"] == "inf" else float(q["exact"])
        out.append(q)
    return j["surface"], out


def _bodies(j, quads):
    out = []
    for b in j:
        group = b.get("physical_group", b["name"])
        if group not in quads:
            raise _Missing(f"bodies: '{group}' is not a physical group of dimension 2")
        element, ids, nodes = quads[group]
        out.append(Body(b["name"], b["role"], float(b["E"]), float(b["nu"]), element, nodes,
                        ids))
    return out


def read_case(path):
    """Reads the case directory `path` (mesh.msh and case.json, docs/solver-protocol.md) into a
    Case of NumPy arrays. Raises ValueError naming the file and the field it cannot read (an
    unknown format version included), and FileNotFoundError for a missing file."""
    path = os.fspath(path)
    case_file = os.path.join(path, "case.json")
    with open(case_file) as f:
        try:
            j = json.load(f)
        except json.JSONDecodeError as e:
            raise ValueError(f"{case_file}: not valid JSON ({e})") from None
    try:
        if j.get("format") != FORMAT or j.get("format_version") != FORMAT_VERSION:
            raise _Missing(f"format '{j.get('format')}' version {j.get('format_version')} is not "
                           f"'{FORMAT}' version {FORMAT_VERSION}")
        mesh_file = os.path.join(path, j["mesh"]["file"])
    except (KeyError, TypeError, _Missing) as e:
        raise ValueError(f"{case_file}: {_why(e)}") from None
    with open(mesh_file) as f:
        text = f.read()
    try:
        nodes = _read_nodes(text)
        elements = _read_elements(text, _entity_groups(text), _physical_names(text))
        quads, edge_sets, node_sets = _mesh_sets(elements, len(nodes))
    except (KeyError, IndexError, ValueError) as e:
        raise ValueError(f"{mesh_file}: {_why(e)}") from None
    try:
        return _case(path, j, nodes, quads, edge_sets, node_sets)
    except (KeyError, IndexError, TypeError, ValueError) as e:
        raise ValueError(f"{case_file}: {_why(e)}") from None


def _why(e):
    if isinstance(e, KeyError):
        return f"the field {e} is missing (or names a set the mesh does not have)"
    return str(e)


def _case(path, j, nodes, quads, edge_sets, node_sets):
    bodies = _bodies(j["bodies"], quads)
    if j["mesh"]["n_nodes"] != len(nodes):
        raise _Missing(f"mesh.n_nodes {j['mesh']['n_nodes']} but mesh.msh has {len(nodes)} nodes")
    constraints = [_constraint(c, node_sets, edge_sets, len(nodes))
                   for c in j["boundary_conditions"]]
    surface, quantities = _sampled(j["sampled"])
    scales = j["scales"]
    return Case(
        path=path, case_id=j["case_id"], problem=j["problem"], mesh_level=j["mesh_level"],
        option=j["option"], analysis=j["analysis"], force_basis=j["force_basis"],
        element=j["mesh"]["element"], nodes=nodes, bodies=bodies, node_sets=node_sets,
        edge_sets=edge_sets, constraints=constraints,
        nodal_forces=_nodal_forces(j["loads"], len(nodes)), contact=_contact(j["contact_pair"]),
        load_control=_load_control(j["load_control"], constraints), p=_float(scales["p"]),
        length_unit=_float(scales["length_unit"]),
        contact_half_width_a=_float(scales["contact_half_width_a"]), sampled_surface=surface,
        sampled_quantities=quantities, result_files=dict(j["results"]), json=j)
