"""The solver protocol from Python (docs/solver-protocol.md): contact_suite.read_case on case
directories the real command writes, and contact_suite.write_results read back and graded by the
engine. The cases come from `contact-suite run --solver` with a code registered in a temporary
--solver-dir: a folder with a manifest and a 17-line script on read_case/write_results that
solves the uniform patch test P_p exactly (option `exact`), or exits 3 so that the engine keeps
the case directory for the test to read (option `keep`).

Environment (tests/CMakeLists.txt): CONTACT_SUITE_EXE, PYTHONPATH (the build's package).
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import contact_suite as cs

EXE = os.environ["CONTACT_SUITE_EXE"]

MANIFEST = {
    "name": "pypatch",
    "description": "the exact uniform patch test on contact_suite.read_case/write_results",
    "command": [sys.executable, "{adapter_dir}/solve.py", "{case_dir}", "{option}"],
    "version_command": [sys.executable, "--version"],
    "options": [
        {"label": "exact", "family": "lagrange_multiplier", "discretization": "ns"},
        {"label": "keep", "family": "penalty", "discretization": "ns"},
    ],
    "supports": ["plane_strain", "axisymmetric", "rigid_target", "meshed_target", "Q4", "Q8"],
    "time_limit_seconds": 60,
}

# The whole code. P_p: the block on a rigid plane under a uniform pressure p on its far face
# has sigma_z = -p, sigma_x = tau_xz = 0, so u_x = nu (1 + nu) p x / E, u_z = -(1 - nu^2) p z / E
# (plane strain, u_z = 0 on the plane).
SCRIPT = '''
import sys
import numpy as np
import contact_suite as cs

case = cs.read_case(sys.argv[1])
if sys.argv[2] == "keep":
    sys.exit(3)  # a failed case's directory is kept
block = case.body("block")
E, nu = block.E, block.nu
p = case.p  # the pressure on the far face, P's normalizing pressure
nodes = case.deformable_nodes
x, z = case.nodes[nodes].T
u = np.column_stack([nu * (1 + nu) * p * x / E, -(1 - nu * nu) * p * z / E])
stress = np.tile([0.0, -p, 0.0, -nu * p], (len(nodes), 1))
surface = np.unique(case.edge_sets[case.contact.contact_surface])
cs.write_results(case.path, nodes=nodes, displacement=u, stress=stress,
                 contact_pressure=np.full(len(surface), p), pressure_nodes=surface,
                 iterations=1, n_equations=2 * len(nodes), solver_version="pypatch 1", case=case)
'''


@pytest.fixture(scope="module")
def code_dir(tmp_path_factory):
    d = tmp_path_factory.mktemp("codes") / "pypatch"
    d.mkdir()
    (d / "manifest.json").write_text(json.dumps(MANIFEST))
    (d / "solve.py").write_text(SCRIPT)
    return d


def run(code_dir, out, option, *selection):
    """`contact-suite run` with the code's `option`; exit 0 (all converged) or 1 (some failed,
    as option keep wants)."""
    r = subprocess.run([EXE, "run", "--solver", "pypatch", "--solver-dir", str(code_dir),
                        "--solver-options", option, "--jobs", "1", "--no-report", "--out",
                        str(out), *selection], capture_output=True, text=True)
    assert r.returncode == (1 if option == "keep" else 0), r.stderr + r.stdout
    return cs.read_results(str(out / "results.json"))


def kept_case_directory(case):
    """The directory the engine kept for a failed case (results.json's kept_files; the reason
    names no directory, so that it is the same in every run)."""
    assert case.status == "failed" and case.kept_files, case.reason
    assert case.kept_files not in case.reason and "kept in" not in case.reason, case.reason
    return Path(case.kept_files)


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """`contact-suite export` of P_p C Q4 and Q8 (discretized target): the same models as CSV."""
    out = tmp_path_factory.mktemp("export") / "cases"
    r = subprocess.run([EXE, "export", "--problems", "P_p", "--meshes", "C", "--elements",
                        "Q4,Q8", "--out", str(out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return out / "models"


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


@pytest.mark.parametrize("element", ["Q4", "Q8"])
def test_read_case_equals_the_exported_model(code_dir, exported, tmp_path, element):
    """Requirement: read_case of a case directory the engine wrote holds the model the C++ code
    built, as `export` writes it from the same model: the same node coordinates to the bit (both
    print 17 significant digits), elements, node sets, materials and nodal forces."""
    doc = run(code_dir, tmp_path / "out", "keep", "--problems", "P_p", "--meshes", "C",
              "--elements", element, "--target", "discretized")
    case = cs.read_case(kept_case_directory(doc.cases[0]))
    model = exported / f"P_p_C_{element}"

    nodes = read_csv(model / "nodes.csv")
    assert case.n_nodes == len(nodes)
    for row in nodes:
        n = int(row["id"]) - 1
        assert tuple(case.nodes[n]) == (float(row["x"]), float(row["y"])), row

    elements = read_csv(model / "elements.csv")
    by_id = {int(e["id"]): e for e in elements}
    assert sum(len(b.elements) for b in case.bodies) == len(elements)
    for index, body in enumerate(case.bodies):
        assert body.element == element
        for eid, conn in zip(body.element_ids, body.elements):
            row = by_id[int(eid)]
            assert row["type"] == element and int(row["body"]) == index
            expected = [int(row[k]) - 1 for k in row if k.startswith("n") and row[k]]
            assert conn.tolist() == expected, (eid, conn, row)

    materials = {m["name"]: m for m in read_csv(model / "materials.csv")}
    for body in case.bodies:
        assert body.E == float(materials[body.name]["E"])
        assert body.nu == float(materials[body.name]["nu"])

    exported_sets = {}  # (name, "nodes"): a node set; (name, "surface"): an edge set's nodes
    for row in read_csv(model / "node_sets.csv"):
        exported_sets.setdefault((row["set"], row["kind"]), set()).add(int(row["node_id"]) - 1)
    for (name, kind), nodes in exported_sets.items():
        got = case.node_sets[name] if kind == "nodes" else np.unique(case.edge_sets[name])
        assert sorted(got.tolist()) == sorted(nodes), (name, kind)

    forces = np.zeros_like(case.nodal_forces)
    for row in read_csv(model / "loads.csv"):
        forces[int(row["node_id"]) - 1] += (float(row["fx"]), float(row["fy"]))
    assert np.array_equal(case.nodal_forces, forces)


def test_read_case_rigid_profile_and_sets(code_dir, tmp_path):
    """Requirement: for a rigid target the case holds the analytic profile; P's plane touches
    the block's contact surface (g = 0 there, to rounding of its coordinates) and the block lies
    on its outer side (g >= 0); the contact surface's nodes are a node set; the options asked
    and the sampled quantities are there."""
    doc = run(code_dir, tmp_path / "out", "keep", "--problems", "P_p,H_p", "--meshes", "C",
              "--elements", "Q8", "--target", "rigid")
    for result in doc.cases:
        case = cs.read_case(kept_case_directory(result))
        # The cases of the two stress bases share one run: its id is one of theirs.
        assert case.option == "keep"
        assert case.case_id.replace("/own/", "/") == result.id.replace("/own/", "/")
        assert case.analysis == "plane_strain" and case.element == "Q8"
        assert case.contact.target_kind == "rigid"
        profile = case.contact.profile
        surface = np.unique(case.edge_sets[case.contact.contact_surface])
        g_surface = profile.signed_distance(*case.nodes[surface].T)
        g_block = profile.signed_distance(*case.nodes[case.body("block").elements.ravel()].T)
        scale = case.length_unit
        assert g_block.min() >= -1e-12 * scale
        if case.problem == "P_p":
            assert profile.type == "plane"
            assert np.all(np.abs(g_surface) <= 1e-12 * scale)
        else:  # Hertz: the cylinder touches the surface at the axis only
            assert profile.type == "circle"
            assert np.min(np.abs(g_surface)) <= 1e-12 * scale < np.max(g_surface)
        assert case.sampled_quantities and all(
            q["component"] in ("sigma_z", "sigma_x") for q in case.sampled_quantities)
        assert case.deformable_nodes.size == len(np.unique(case.body("block").elements))
        dofs, values = case.prescribed()
        assert dofs.size and np.all(np.isfinite(values))


def test_python_results_are_read_back_and_graded(code_dir, tmp_path):
    """Requirement: a code of one folder (manifest + script on read_case/write_results) is run
    and graded like any solver: the exact patch-test field gives sigma_z = -p on both bases to
    rounding (the own basis reads back write_results' numbers: -sigma_z/p is exactly 1), and its
    contact pressure p is graded."""
    doc = run(code_dir, tmp_path / "out", "exact", "--problems", "P_p", "--meshes", "C",
              "--elements", "Q4,Q8", "--target", "rigid")
    ids = sorted(c.id for c in doc.cases)
    assert ids == sorted(f"P_p/C/{e}/LMP/ns/rigid{b}/@pypatch:exact"
                         for e in ("Q4", "Q8") for b in ("", "/own"))
    for case in doc.cases:
        assert case.status == "converged", case.reason
        q = next(q for q in case.quantities if q.quantity == "sigma_z_max")
        if case.id.endswith("/own/@pypatch:exact"):
            assert q.value == 1.0  # the stress written, read back bit for bit, over p
        else:  # our recovery of the exact linear field: machine precision x a few hundred ops
            assert abs(q.error_percent) < 1e-9


# ---- write_results on its own -----------------------------------------------------------------

def test_write_results_layout(tmp_path):
    """Requirement: the files are the documented layout: headers, 1-based ids, numbers that read
    back to the same doubles, status.json's keys."""
    u = np.array([[0.1, -1e-300], [1 / 3, 2.0]])
    cs.write_results(tmp_path, nodes=np.array([4, 0]), displacement=u,
                     stress=np.array([[1.0, 2.0, 3.0, 4.0]]), stress_nodes=[0],
                     contact_pressure=[0.5], pressure_nodes=[4], converged=False, iterations=7,
                     n_equations=10, reason="stalled", solver_version="x 1")
    lines = (tmp_path / "displacements.csv").read_text().splitlines()
    assert lines[0] == "node_id,ux,uz" and lines[1].startswith("5,")
    back = np.array([[float(v) for v in ln.split(",")[1:]] for ln in lines[1:]])
    assert np.array_equal(back, u)
    assert (tmp_path / "stresses.csv").read_text() == \
        "node_id,sigma_x,sigma_z,tau_xz,sigma_out_of_plane\n1,1.0,2.0,3.0,4.0\n"
    assert (tmp_path / "contact_pressure.csv").read_text() == "node_id,pressure\n5,0.5\n"
    assert json.loads((tmp_path / "status.json").read_text()) == {
        "converged": False, "iterations": 7, "n_equations": 10, "reason": "stalled",
        "solver_version": "x 1"}


@pytest.mark.parametrize("kwargs, field", [
    (dict(displacement=[[0.0, math.nan], [0.0, 0.0]]), "displacement"),
    (dict(displacement=[[0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]), "displacement"),
    (dict(displacement=np.zeros((3, 2))), "displacement"),
    (dict(nodes=[1, 1]), "nodes"),
    (dict(nodes=[0.0, 1.0]), "nodes"),
    (dict(nodes=[-1, 0]), "nodes"),
    (dict(stress=np.zeros((2, 3))), "stress"),
    (dict(stress=[[0, 0, 0, math.inf]] * 2), "stress"),
    (dict(contact_pressure=[1.0]), "pressure_nodes"),
    (dict(contact_pressure=[math.nan], pressure_nodes=[0]), "contact_pressure"),
    (dict(iterations=-1), "iterations"),
    (dict(converged="yes"), "converged"),
])
def test_write_results_refuses_bad_values(tmp_path, kwargs, field):
    """Requirement: NaN, infinities, wrong shapes, repeated or negative nodes and bad status
    values raise ValueError naming the field, and nothing is written."""
    args = dict(nodes=[0, 1], displacement=np.zeros((2, 2)))
    args.update(kwargs)
    with pytest.raises(ValueError, match=f"^{field}:"):
        cs.write_results(tmp_path, **args)
    assert list(tmp_path.iterdir()) == []


def test_read_case_refuses_an_unknown_version(tmp_path):
    """Requirement: a case.json of another format version raises ValueError naming the file."""
    (tmp_path / "case.json").write_text('{"format": "contact-suite case", "format_version": 2}')
    with pytest.raises(ValueError, match="case.json: .*version 2"):
        cs.read_case(tmp_path)


def test_read_case_refuses_a_node_id_out_of_range(code_dir, tmp_path):
    """Requirement: a node id of 0 (or beyond the mesh) in case.json raises ValueError naming
    the field; it never reads another node's entry from the end of an array."""
    doc = run(code_dir, tmp_path / "out", "keep", "--problems", "P_p", "--meshes", "C",
              "--elements", "Q4", "--target", "rigid")
    case_dir = tmp_path / "case"
    shutil.copytree(kept_case_directory(doc.cases[0]), case_dir)
    j = json.loads((case_dir / "case.json").read_text())
    assert j["loads"]["nodal_forces"]
    j["loads"]["nodal_forces"][0][0] = 0
    (case_dir / "case.json").write_text(json.dumps(j))
    with pytest.raises(ValueError, match="loads.nodal_forces: node id 0 is not in 1.."):
        cs.read_case(case_dir)


@pytest.mark.parametrize("tag", ["0", "n+1"])
def test_read_case_refuses_a_mesh_node_tag_out_of_range(code_dir, tmp_path, tag):
    """Requirement: an element of mesh.msh naming node 0 (or a node beyond the mesh) raises
    ValueError naming the file and the group; it never reads the last node for node 0."""
    doc = run(code_dir, tmp_path / "out", "keep", "--problems", "P_p", "--meshes", "C",
              "--elements", "Q4", "--target", "rigid")
    case_dir = tmp_path / "case"
    shutil.copytree(kept_case_directory(doc.cases[0]), case_dir)
    lines = (case_dir / "mesh.msh").read_text().split("\n")
    n_nodes = int(lines[lines.index("$Nodes") + 1].split()[1])
    start = lines.index("$Elements") + 2
    header = next(k for k in range(start, len(lines)) if lines[k].split()[2:3] == ["3"])
    row = lines[header + 1].split()
    row[1] = "0" if tag == "0" else str(n_nodes + 1)
    lines[header + 1] = " ".join(row)
    (case_dir / "mesh.msh").write_text("\n".join(lines))
    with pytest.raises(ValueError, match=f"mesh.msh: .*group '.*': node id {row[1]} is not in "
                                         f"1..{n_nodes}"):
        cs.read_case(case_dir)


def test_signed_distances():
    """Requirement: the profiles' signed distance is the documented formula (values by hand)."""
    plane = cs.RigidProfile("plane", {"point": (0.0, 0.0), "normal": (0.0, 1.0)})
    assert plane.signed_distance(3.0, 2.0) == 2.0
    circle = cs.RigidProfile("circle", {"center": (0.0, -5.0), "radius": 5.0})
    assert np.allclose(circle.signed_distance([0.0, 3.0], [0.0, -1.0]), [0.0, 0.0])
    punch = cs.RigidProfile("rounded_flat_punch", {"face_center": (0.0, 0.0),
                                                   "direction": (0.0, 1.0),
                                                   "half_width_b": 1.0, "edge_radius_re": 1.0})
    # on the face; beside the rounded edge at 45 degrees, sqrt(2) - 1 off its arc; outside it
    g = punch.signed_distance([0.5, 2.0, 3.0], [0.25, 0.0, -2.0])
    assert np.allclose(g, [0.25, math.sqrt(2.0) - 1.0, 1.0], rtol=1e-15)
    sharp = cs.RigidProfile("sharp_flat_punch", {"face_center": (0.0, 0.0),
                                                 "direction": (0.0, 1.0), "half_width_a": 1.0})
    assert np.allclose(sharp.signed_distance([0.0, 5.0, 2.0], [1.0, 3.0, -1.0]), [1.0, 5.0, 1.0])
