"""The writer of what an external code returns into its case directory (docs/solver-protocol.md,
section 3), exactly the layout the engine reads back (adapters/protocol/result_files.hpp):

    displacements.csv     node_id,ux,uz                                       required
    stresses.csv          node_id,sigma_x,sigma_z,tau_xz,sigma_out_of_plane    optional
    contact_pressure.csv  node_id,pressure                                    optional
    status.json           {"converged", "iterations", "n_equations", "reason", "solver_version"}

Nodes are given as indices (node id - 1, as read_case gives them); every number is written
with Python's shortest repr, which reads back to the same double.
"""
import json
import os

import numpy as np


def _nodes(name, nodes, n_nodes):
    a = np.asarray(nodes)
    if a.ndim != 1 or (a.size and not np.issubdtype(a.dtype, np.integer)):
        raise ValueError(f"{name}: expected a 1-D array of node indices (ints), got shape "
                         f"{a.shape} of {a.dtype}")
    a = a.astype(np.int64)
    if a.size and a.min() < 0:
        raise ValueError(f"{name}: node index {int(a.min())} is negative")
    if n_nodes is not None and a.size and a.max() >= n_nodes:
        raise ValueError(f"{name}: node index {int(a.max())} is not below the mesh's {n_nodes} "
                         "nodes")
    unique, counts = np.unique(a, return_counts=True)
    if np.any(counts > 1):
        raise ValueError(f"{name}: node index {int(unique[counts > 1][0])} is given twice")
    return a


def _values(name, values, nodes, columns):
    """`values` as a float array of shape (len(nodes), columns) (or (len(nodes),) for one
    column), finite."""
    try:
        a = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name}: not an array of numbers") from None
    shape = (len(nodes),) if columns == 1 else (len(nodes), columns)
    if a.shape != shape:
        raise ValueError(f"{name}: shape {a.shape}, expected {shape} (one row per node)")
    bad = ~np.isfinite(a)
    if np.any(bad):
        row = int(np.argwhere(bad)[0][0])
        raise ValueError(f"{name}: value {a.reshape(len(nodes), -1)[row].tolist()} at node index "
                         f"{int(nodes[row])} is not finite")
    return a.reshape(len(nodes), columns)


def _csv(header, nodes, values):
    rows = [header]
    for n, row in zip(nodes.tolist(), values.tolist()):
        rows.append(",".join([str(n + 1)] + [repr(float(v)) for v in row]))
    return "\n".join(rows) + "\n"


def write_results(path, *, nodes, displacement, stress=None, stress_nodes=None,
                  contact_pressure=None, pressure_nodes=None, converged=True, iterations=0,
                  n_equations=0, reason="", solver_version="", case=None):
    """Writes a code's results into the case directory `path`.

    nodes             node indices (int array (k,)): at least every node of every deformable
                      body (Case.deformable_nodes)
    displacement      (k, 2): (u_x, u_z) at `nodes` [length]
    stress            optional (m, 4): the code's own nodal stresses (sigma_x, sigma_z, tau_xz,
                      sigma_out_of_plane) [units of p, tension positive] at `stress_nodes`
                      (default `nodes`); graded on the `own` basis
    contact_pressure  optional (j,): the nodal contact pressure [units of p, > 0 in
                      compression] at `pressure_nodes` (required with it), e.g. the contact
                      surface's nodes
    converged, iterations, n_equations, reason, solver_version   status.json; converged False
                      makes the case not_converged with `reason`
    case              optional Case (read_case): the indices are checked against its nodes and
                      every deformable node must have a displacement

    Nothing is written unless everything is valid: a wrong shape, a NaN or infinite value, a
    node given twice or out of range raises ValueError naming the field. The engine measures
    the wall time and memory itself.
    """
    n_nodes = None if case is None else case.n_nodes
    nodes = _nodes("nodes", nodes, n_nodes)
    u = _values("displacement", displacement, nodes, 2)
    if case is not None:
        missing = np.setdiff1d(case.deformable_nodes, nodes)
        if missing.size:
            raise ValueError(f"nodes: node index {int(missing[0])} of a deformable body has no "
                             "displacement")
    files = {"displacements.csv": _csv("node_id,ux,uz", nodes, u)}
    if stress is not None:
        at = nodes if stress_nodes is None else _nodes("stress_nodes", stress_nodes, n_nodes)
        files["stresses.csv"] = _csv("node_id,sigma_x,sigma_z,tau_xz,sigma_out_of_plane", at,
                                     _values("stress", stress, at, 4))
    elif stress_nodes is not None:
        raise ValueError("stress_nodes: given without stress")
    if contact_pressure is not None:
        if pressure_nodes is None:
            raise ValueError("pressure_nodes: required with contact_pressure")
        at = _nodes("pressure_nodes", pressure_nodes, n_nodes)
        files["contact_pressure.csv"] = _csv("node_id,pressure", at,
                                             _values("contact_pressure", contact_pressure, at, 1))
    elif pressure_nodes is not None:
        raise ValueError("pressure_nodes: given without contact_pressure")
    files["status.json"] = json.dumps(_status(converged, iterations, n_equations, reason,
                                              solver_version)) + "\n"
    for name, text in files.items():
        with open(os.path.join(os.fspath(path), name), "w") as f:
            f.write(text)


def _status(converged, iterations, n_equations, reason, solver_version):
    if not isinstance(converged, (bool, np.bool_)):
        raise ValueError(f"converged: {converged!r} is not a bool")
    for name, v in (("iterations", iterations), ("n_equations", n_equations)):
        if not isinstance(v, (int, np.integer)) or isinstance(v, bool) or v < 0:
            raise ValueError(f"{name}: {v!r} is not a non-negative int")
    for name, v in (("reason", reason), ("solver_version", solver_version)):
        if not isinstance(v, str):
            raise ValueError(f"{name}: {v!r} is not a string")
    return {"converged": bool(converged), "iterations": int(iterations),
            "n_equations": int(n_equations), "reason": reason, "solver_version": solver_version}
