#!/usr/bin/env python3
"""Writes small_results.json: a hand-made results file (schema contact-suite/results v3,
docs/results-schema.md) for the tests of reports/. The values are invented near the study's
(they exercise the tables; they are not solver output). Rows follow the schema's rules:
grade of the finest mesh present, converging as in suites/grading.hpp, Eq. 47 for F_p/F_a.
The `problems` records are those the run writes from each problem's descriptor (titles,
study tables, quantity definitions), for the problems that have a case, in battery order.
This script only writes the file; the results are read by the C++ reader (schema/) alone.

Run: python3 make_small_results.py > small_results.json
"""
import json
import math

HERTZ = 4 / math.pi
STEUERMANN_1_3 = 11.2424
MESHES = ["C", "M", "F"]
H = {"P": [0.25, 0.125, 0.0625], "H": [0.125, 0.0625, 0.03125],
     "S": [0.04, 0.02, 0.01], "F": [0.0625, 0.03125, 0.015625]}


def grade(err):
    e = abs(err)
    return "e" if e < 1 else "g" if e < 5 else "s" if e < 10 else "u"


def converging(errs):
    c, m, f = (abs(e) for e in errs)
    tol = 0.01
    return (m <= c + tol and f <= m + tol) and (f < c - tol or c <= tol)


def hertz_profile(n, edge_shift, scale):
    xs = [1.5 * i / (n - 1) for i in range(n)]
    ys = [HERTZ * scale * math.sqrt(max(0.0, 1 - (x / (1 + edge_shift)) ** 2)) for x in xs]
    return xs, ys


def steuermann_shape(x, peak, edge):
    """A hand-made Steuermann-like curve: low in the flat part, a peak over the rounded edge,
    down to zero at the edge of contact (x = edge)."""
    if x < 1:
        return 1.2 + 0.3 * x * x
    top = edge - 0.08
    if x < top:
        t = (x - 1) / (top - 1)
        return 1.5 + (peak - 1.5) * math.sin(0.5 * math.pi * t) ** 2
    if x < edge:
        return peak * math.sqrt((edge - x) / (edge - top))
    return 0.0


def profile_for(problem, mesh_index, value):
    n = [13, 25, 49][mesh_index]
    if problem == "H_p":
        xs, ys = hertz_profile(n, 0.12 / 2 ** mesh_index, value / HERTZ)
        return {"x_over_a": xs, "sigma_z_over_p": ys, "pressure_over_p": [0.99 * y for y in ys]}
    if problem == "S_1_3":
        xs = [1.6 * i / (n - 1) for i in range(n)]
        ys = [steuermann_shape(x, value, 1.3333 + 0.06 / 2 ** mesh_index) for x in xs]
        return {"x_over_a": xs, "sigma_z_over_p": ys, "pressure_over_p": ys}
    return {"x_over_a": [], "sigma_z_over_p": [], "pressure_over_p": []}


def exact_profile_for(problem):
    if problem == "H_p":
        xs, ys = hertz_profile(151, 0.0, 1.0)
        return {"x_over_a": xs, "sigma_z_over_p": ys}
    if problem == "S_1_3":
        xs = [1.6 * i / 400 for i in range(401)]
        return {"x_over_a": xs, "sigma_z_over_p": [steuermann_shape(x, STEUERMANN_1_3, 1.3333) for x in xs]}
    return None


# The battery's problems in order, as their descriptors describe them (suites/problems/).
def patch_quantity(table):
    return {"quantity": "sigma_z_max", "definition_md": "−σ<sub>z</sub><sup>max</sup>/p",
            "definition_plain": "-sigma_z^max/p", "study_table": table, "study_row": "main"}


def centre_quantity(table, row="main"):
    return {"quantity": "sigma_c", "definition_md": "−σ<sub>z</sub>(0, 0)/p",
            "definition_plain": "-sigma_z(0,0)/p", "study_table": table, "study_row": row}


def steuermann_quantity(table):
    return {"quantity": "sigma_c", "definition_md": "max of −σ<sub>z</sub>/p on z = 0",
            "definition_plain": "max -sigma_z/p on z = 0", "study_table": table,
            "study_row": "main"}


def punch_quantity(table):
    return {"quantity": "sigma_c_star", "definition_md": "−σ<sub>z</sub>(a, 0)/p",
            "definition_plain": "-sigma_z(a,0)/p", "study_table": table, "study_row": ""}


# The situation and length scale each problem's descriptor declares.
FACTS = {"P_p": "matched_patch", "P_a": "matched_patch", "Pprime_p": "mismatched_patch",
         "Pprime_a": "mismatched_patch", "H_p": "smooth_curved", "H_a": "smooth_curved",
         "S_1": "rounded_punch", "S_1_3": "rounded_punch", "S_1_7": "rounded_punch",
         "F_p": "flat_punch", "F_a": "flat_punch"}


def problem(pid, title, description, axisymmetric, singular, tables, source, quantities):
    return {"id": pid, "title": title, "description": description, "axisymmetric": axisymmetric,
            "singular": singular, "study_tables": tables, "exact_source": source,
            "quantities": quantities, "situation": FACTS[pid],
            "length_scale": "punch_half_width_b" if pid.startswith("S_")
            else "contact_half_width_a"}


PROBLEMS = [
    problem("P_p", "Contact patch test, matched nodes (plane strain)",
            "plane-strain contact patch test, matched nodes", False, False, "3", "Eq. 6",
            [patch_quantity("3")]),
    problem("P_a", "Contact patch test, matched nodes (axisymmetric)",
            "axisymmetric contact patch test, matched nodes", True, False, "5", "Eq. 8",
            [patch_quantity("5")]),
    problem("Pprime_p", "Contact patch test, mismatched nodes (plane strain)",
            "plane-strain contact patch test, mismatched nodes", False, False, "4", "Eq. 6",
            [patch_quantity("4")]),
    problem("Pprime_a", "Contact patch test, mismatched nodes (axisymmetric)",
            "axisymmetric contact patch test, mismatched nodes", True, False, "6", "Eq. 8",
            [patch_quantity("6")]),
    problem("H_p", "Hertz contact of a cylinder (plane strain)", "plane-strain Hertzian contact",
            False, False, "7, 8", "Eq. 15",
            [centre_quantity("7", "contact"),
             {"quantity": "sigma_h", "definition_md": "−σ<sub>x</sub>(0, 0)/p",
              "definition_plain": "-sigma_x(0,0)/p", "study_table": "8",
              "study_row": "horizontal"}]),
    problem("H_a", "Hertz contact of a sphere (axisymmetric)", "axisymmetric Hertzian contact",
            True, False, "9", "Eq. 22", [centre_quantity("9")]),
    problem("S_1", "Steuermann punch, r_e/b = 1", "plane-strain Steuermann contact, r_e/b = 1",
            False, False, "10", "Eq. 31", [steuermann_quantity("10")]),
    problem("S_1_3", "Steuermann punch, r_e/b = 1/3",
            "plane-strain Steuermann contact, r_e/b = 1/3", False, False, "11", "Eq. 31",
            [steuermann_quantity("11")]),
    problem("S_1_7", "Steuermann punch, r_e/b = 1/7",
            "plane-strain Steuermann contact, r_e/b = 1/7", False, False, "12", "Eq. 31",
            [steuermann_quantity("12")]),
    problem("F_p", "Sadowsky flat punch (plane strain)", "plane-strain flat punch", False, True,
            "13", "Eq. 39", [punch_quantity("13")]),
    problem("F_a", "Harding-Sneddon flat punch (axisymmetric)", "axisymmetric flat punch", True,
            True, "14", "Eq. 45", [punch_quantity("14")]),
]

cases, rows = [], []


def add(problem, element, algorithm, contact, quantities, statuses=None, target="discretized",
        overrides=None, missing=(), recovery="spr"):
    """quantities: name -> (exact or 'inf', [C, M, F] values, study_exact or None)."""
    statuses = statuses or ["converged"] * 3
    overrides = overrides or {}
    family = problem[0] if problem[0] != "P" else "P"
    suffix = ("/rigid" if target == "rigid" else "") + (
        "/extrapolated" if recovery == "extrapolated" else "") + "".join(
        f"/{k}={v:g}" for k, v in sorted(overrides.items()))
    per_row = {name: {"values": {}, "errors": {}} for name in quantities}
    for mi, mesh in enumerate(MESHES):
        if mesh in missing:
            for name in quantities:
                per_row[name]["values"][mesh] = None
                per_row[name]["errors"][mesh] = None
            continue
        status = statuses[mi]
        qs = {}
        for name, (exact, values, study_exact) in quantities.items():
            v = values[mi] if status != "failed" else None
            singular = exact == "inf"
            err = None if v is None else (0.0 if singular else 100 * (v - exact) / abs(exact))
            q = {"value": v, "exact": exact, "error_percent": err,
                 "grade": "u" if (singular or err is None) else grade(err),
                 "contact_pressure": None if v is None else round(0.995 * v, 6)}
            if study_exact is not None:
                q["study_exact"] = study_exact
            qs[name] = q
            per_row[name]["values"][mesh] = v
            per_row[name]["errors"][mesh] = None if singular else err
        first = next(iter(quantities.values()))
        case = {
            "id": f"{problem}/{mesh}/{element}/{algorithm}/{contact}{suffix}",
            "problem": problem, "mesh": mesh, "element": element, "algorithm": algorithm,
            "contact": contact, "target": target, "recovery": recovery, "solver": "builtin",
            "overrides": overrides, "status": status,
            "reason": {"converged": "", "not_converged": "active set cycling after 40 iterations",
                       "failed": "singular stiffness matrix (rigid body mode)"}[status],
            "iterations": 0 if status == "failed" else 3 + mi,
            "wall_seconds": round(0.05 * 4 ** mi * (2 if element == "Q8" else 1), 3),
            "peak_rss_mb": 120.0 + 40 * mi,
            "n_elements": 64 * 4 ** mi, "n_equations": 300 * 4 ** mi,
            "element_size_h": H[family][mi],
            "quantities": qs,
            "profile": profile_for(problem, mi, first[1][mi]) if status != "failed" else
            {"x_over_a": [], "sigma_z_over_p": [], "pressure_over_p": []},
        }
        ex = exact_profile_for(problem)
        if ex is not None:
            case["exact_profile"] = ex
        cases.append(case)
    for name, (exact, _, _) in quantities.items():
        vals, errs = per_row[name]["values"], per_row[name]["errors"]
        singular = exact == "inf"
        finest = next((m for m in reversed(MESHES) if errs[m] is not None), None)
        complete = all(vals[m] is not None for m in MESHES)
        row = {
            "id": f"{problem}/{element}/{algorithm}/{contact}{suffix}/{name}",
            "problem": problem, "element": element, "algorithm": algorithm, "contact": contact,
            "target": target, "recovery": recovery, "solver": "builtin", "overrides": overrides,
            "quantity": name, "values": vals, "error_percent": errs,
            "grade": None if singular or finest is None else grade(errs[finest]),
            "graded_mesh": None if singular or finest is None else finest,
            "converging": None if singular or not complete else converging([errs[m] for m in MESHES]),
            "diverging": (abs(vals["C"] - vals["M"]) < abs(vals["M"] - vals["F"]))
            if singular and complete else None,
        }
        rows.append(row)


# Contact patch test, matched nodes (the study's Table 3): AL ss exact on every mesh.
add("P_p", "Q4", "AL", "ss", {"sigma_z_max": (1.0, [1.0, 1.0, 1.0], None)})
add("P_p", "Q4", "LMP", "ss", {"sigma_z_max": (1.0, [1.0001, 1.0003, 1.0019], None)})
# Mismatched nodes: AL ss like ANSYS, mortar much better.
add("Pprime_p", "Q4", "AL", "ss", {"sigma_z_max": (1.0, [1.0425, 1.0425, 1.0425], None)})
add("Pprime_p", "Q4", "LMP", "mortar", {"sigma_z_max": (1.0, [1.0008, 1.0004, 1.0002], None)})
# Plane-strain Hertz, Q4: AL and PM coincide; LMP and PLM coincide; MPC; AL ns; LMP mortar.
hp = lambda c, h: {"sigma_c": (HERTZ, c, None), "sigma_h": (HERTZ, h, None)}
add("H_p", "Q4", "AL", "ss", hp([1.2650, 1.2711, 1.2730], [1.2150, 1.2230, 1.2260]))
add("H_p", "Q4", "PM", "ss", hp([1.2650, 1.2711, 1.2730], [1.2150, 1.2230, 1.2260]))
add("H_p", "Q4", "LMP", "ss", hp([1.3100, 1.2900, 1.2790], [1.3600, 1.3300, 1.3000]))
add("H_p", "Q4", "PLM", "ss", hp([1.3100, 1.2900, 1.2790], [1.3600, 1.3300, 1.3000]))
add("H_p", "Q4", "MPC", "ss", hp([1.4400, 1.4700, 1.5200], [2.2000, 2.3000, 2.4000]),
    statuses=["converged", "converged", "not_converged"])
add("H_p", "Q4", "AL", "ns", hp([1.3400, 1.3300, 1.3100], [1.3700, 1.3900, 1.4000]))
add("H_p", "Q4", "LMP", "mortar", hp([1.2700, 1.2725, 1.2731], [1.2500, 1.2650, 1.2710]))
# Q8: AL ss without its fine mesh (missing); PM ss with a failed fine mesh.
add("H_p", "Q8", "AL", "ss", hp([1.2960, 1.2810, 0.0], [1.2190, 1.2215, 0.0]), missing=("F",))
add("H_p", "Q8", "PM", "ss", hp([1.2960, 1.2810, 1.2760], [1.2190, 1.2215, 1.2240]),
    statuses=["converged", "converged", "failed"])
# Steuermann r_e/b = 1/3: graded against 11.2424, the study printed 10.9571.
add("S_1_3", "Q4", "AL", "ss", {"sigma_c": (STEUERMANN_1_3, [9.0100, 9.4600, 9.5300], 10.9571)})
add("S_1_3", "Q4", "LMP", "ss", {"sigma_c": (STEUERMANN_1_3, [10.3000, 10.9000, 11.1500], 10.9571)})
# Flat punch: AL ss diverges; MPC ss does not (|C-M| = 0.5 > |M-F| = 0.3).
add("F_p", "Q4", "AL", "ss", {"sigma_c_star": ("inf", [2.1300, 3.0200, 4.2700], None)})
add("F_p", "Q4", "MPC", "ss", {"sigma_c_star": ("inf", [2.0000, 2.5000, 2.8000], None)})
# Variants: a rigid target and a penalty-stiffness override (not in the study's tables).
add("H_p", "Q4", "AL", "ss", hp([1.2660, 1.2715, 1.2731], [1.2160, 1.2235, 1.2262]), target="rigid")
add("H_p", "Q4", "PM", "ss", hp([1.2500, 1.2600, 1.2650], [1.2000, 1.2100, 1.2150]),
    overrides={"fkn": 10.0})
add("H_p", "Q4", "LMP", "ss", hp([1.3311, 1.3012, 1.2892], [1.2066, 1.2573, 1.2668]),
    recovery="extrapolated")

doc = {
    "schema": "contact-suite/results",
    "schema_version": 3,
    "run": {
        "started_utc": "2026-11-22T10:00:00Z", "wall_seconds": 12.5, "jobs": 2,
        "peak_rss_mb": 310.5, "command_line": "contact-suite run --out out --problems H_p,P_p",
        "environment": {"hostname": "testhost", "cores": 2, "compiler": "GCC 12.2.0",
                        "version": "0.1.0", "blas": "OpenBLAS",
                        "solver": {"factorization": "CHOLMOD supernodal", "max_iterations": 40}},
    },
    "problems": [p for p in PROBLEMS if any(c["problem"] == p["id"] for c in cases)],
    "cases": cases,
    "rows": rows,
}
print(json.dumps(doc, indent=1))
