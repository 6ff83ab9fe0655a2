#!/usr/bin/env python3
"""A stand-in external code for the solver protocol's tests (docs/solver-protocol.md).

It solves the uniform contact patch test P_p exactly: the block on a rigid plane z = 0 under a
uniform pressure on its far face carries sigma_z = -p, sigma_x = tau_xz = 0 everywhere, so
u_x = nu (1 + nu) p x / E and u_z = -(1 - nu^2) p z / E (plane strain; u_z = 0 on the plane).
p is read off the case's nodal forces on block.far_z, E and nu off its block body. It writes
every result file of the protocol. Its option label selects a failure to exercise the engine:
exact (none), exit3, nan, missing_node, unparsable, outside, sleep, no_stresses, multiline,
surface_stress_missing, pressure_twice, pressure_off_surface, bad_count, deep_status
(not converged, for a reason of several lines).

Usage: patch_solver.py CASE_DIR OPTION
"""
import json
import os
import sys
import time


def read_nodes(msh_path):
    """Node tag -> (x, z) from a Gmsh MSH 4.1 ASCII file."""
    with open(msh_path) as f:
        lines = f.read().split("\n")
    start = lines.index("$Nodes")
    n_blocks = int(lines[start + 1].split()[0])
    at = start + 2
    nodes = {}
    for _ in range(n_blocks):
        count = int(lines[at].split()[3])
        tags = [int(t) for t in lines[at + 1:at + 1 + count]]
        for k, tag in enumerate(tags):
            x, y, _ = (float(v) for v in lines[at + 1 + count + k].split())
            nodes[tag] = (x, y)
        at += 1 + 2 * count
    return nodes, lines


def body_nodes(lines, entity_tag):
    """The node tags of the 2D elements of entity `entity_tag` (a body's physical group)."""
    start = lines.index("$Elements")
    n_blocks = int(lines[start + 1].split()[0])
    at = start + 2
    out = set()
    for _ in range(n_blocks):
        dim, tag, _, count = (int(v) for v in lines[at].split())
        for row in lines[at + 1:at + 1 + count]:
            if dim == 2 and tag == entity_tag:
                out.update(int(v) for v in row.split()[1:])
        at += 1 + count
    return sorted(out)


def main():
    case_dir, option = sys.argv[1], sys.argv[2]
    with open(os.path.join(case_dir, "case.json")) as f:
        case = json.load(f)
    nodes, lines = read_nodes(os.path.join(case_dir, case["mesh"]["file"]))
    block = next(b for b in case["bodies"] if b["name"] == "block")
    E, nu = block["E"], block["nu"]
    far_z = max(z for _, z in nodes.values())  # the block's far face z = h
    # p from the far face's consistent nodal forces: their z sum is -p times its width.
    on_far = [f for f in case["loads"]["nodal_forces"] if abs(nodes[f[0]][1] - far_z) < 1e-12]
    width = max(nodes[f[0]][0] for f in on_far) - min(nodes[f[0]][0] for f in on_far)
    p = -sum(f[2] for f in on_far) / width
    names = [b["name"] for b in case["bodies"]]
    block_nodes = body_nodes(lines, names.index("block") + 1)
    surface = [t for t in block_nodes if abs(nodes[t][1]) < 1e-12]  # the contact face z = 0

    if option == "exit3":
        print("patch solver: progress line", file=sys.stderr)
        sys.stderr.flush()
        # Not UTF-8 (Latin-1 "é", a lone 0xff): a code's stderr is bytes, not text.
        sys.stderr.buffer.write(b"patch solver: cannot solve this case (r\xe9gime \xff)\n\n")
        sys.exit(3)
    if option == "sleep":
        time.sleep(60)
    if option == "outside":
        open(os.path.join(case_dir, "..", "stray.txt"), "w").write("x")

    with open("displacements.csv", "w") as f:
        f.write("node_id,ux,uz\n")
        for t in block_nodes:
            if option == "missing_node" and t == block_nodes[-1]:
                continue
            x, z = nodes[t]
            ux = nu * (1 + nu) * p * x / E
            uz = -(1 - nu * nu) * p * z / E
            if option == "nan" and t == block_nodes[0]:
                uz = float("nan")
            f.write(f"{t},{ux!r},{'1.2.3' if option == 'unparsable' else repr(uz)}\n")
    if option != "no_stresses":
        with open("stresses.csv", "w") as f:
            f.write("node_id,sigma_x,sigma_z,tau_xz,sigma_out_of_plane\n")
            for t in block_nodes:
                if option == "surface_stress_missing" and t == surface[0]:
                    continue
                f.write(f"{t},0,{-p!r},0,{-nu * p!r}\n")
    with open("contact_pressure.csv", "w") as f:
        f.write("node_id,pressure\n")
        for t in surface:
            f.write(f"{t},{p!r}\n")
        if option == "pressure_twice":
            f.write(f"{surface[0]},{p!r}\n")
        if option == "pressure_off_surface":
            f.write(f"{next(t for t in block_nodes if t not in surface)},{p!r}\n")
    if option == "deep_status":
        with open("status.json", "w") as f:
            f.write('{"iterations": ' + "[" * 100000 + "]" * 100000 + "}")
        return
    with open("status.json", "w") as f:
        converged = option != "multiline"
        reason = "" if converged else "iteration cap\nreached\tat step 3"
        iterations = 1e20 if option == "bad_count" else 1
        json.dump({"converged": converged, "iterations": iterations,
                   "n_equations": 2 * len(block_nodes),
                   "reason": reason, "solver_version": "patch-solver 1"}, f)


if __name__ == "__main__":
    main()
