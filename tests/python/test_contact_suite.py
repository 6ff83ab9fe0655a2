"""The Python module contact_suite (python/), run by ctest (test `python_module`) with Debian's
python3 and pytest. Environment, set by tests/CMakeLists.txt:
  PYTHONPATH                        the build's python/ directory (the module)
  CONTACT_SUITE_ORACLE_REFERENCE    tests/python/oracle_reference.cpp, built
  CONTACT_SUITE_EXE                 the contact-suite command
  CONTACT_SUITE_SOURCE_DIR          the source tree (oracles/ headers, the results fixture)
"""
import json
import math
import os
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

import contact_suite as cs

SOURCE = Path(os.environ["CONTACT_SUITE_SOURCE_DIR"])
EXE = os.environ["CONTACT_SUITE_EXE"]
FIXTURE = SOURCE / "tests/reports/data/small_results.json"


def reference_entries():
    out = subprocess.run([os.environ["CONTACT_SUITE_ORACLE_REFERENCE"]], check=True,
                         capture_output=True, text=True).stdout
    return [json.loads(line) for line in out.splitlines()]


REFERENCE = reference_entries()


def as_dict(value):
    """A result object's fields (or a dict) as a dict."""
    if isinstance(value, dict):
        return value
    return {k: getattr(value, k) for k in dir(value) if not k.startswith("_")}


@pytest.mark.parametrize("entry", REFERENCE, ids=[e["function"] for e in REFERENCE])
def test_oracle_equals_cpp(entry):
    """Requirement: every oracle through Python equals its C++ value bit for bit (the same
    compiled code: any difference is an argument passed to the wrong parameter or a field
    returned under the wrong name)."""
    function = getattr(cs, entry["function"])
    if "contact" in entry:
        contact = getattr(cs, entry["contact"]["function"])(**entry["contact"]["args"])
        result = function(contact, **entry["args"])
    else:
        result = function(**entry["args"])
    expected = entry["result"]
    if isinstance(expected, dict):
        got = as_dict(result)
        for key, value in expected.items():
            assert got[key] == value, (key, got[key], value)
    else:
        assert result == expected


def declared_oracles():
    """The functions declared in oracles/*.hpp (less the helpers that are not oracles)."""
    helpers = {"format_value", "require_positive", "require_non_negative", "require_finite",
               "require_poisson_ratio", "require_friction_coefficient",
               "require_in_half_space", "to_string", "length_scale", "mcewen_roots",
               "radial_line_load_stress",
               "integrate", "integrate_with_breakpoints", "integrate_to_infinity",
               "integrate_algebraic_ends", "integrate_cauchy_principal_value"}
    names = set()
    for header in (SOURCE / "oracles").glob("*.hpp"):
        for m in re.finditer(r"^[A-Za-z][\w:<>]*\s+(\w+)\(", header.read_text(), re.M):
            names.add(m.group(1))
    return names - helpers


def test_every_oracle_is_bound_and_compared():
    """Requirement: every oracle of oracles/ is in the module and in the comparison above."""
    declared = declared_oracles()
    assert len(declared) > 30
    compared = {e["function"] for e in REFERENCE}
    assert declared - compared == set()
    assert all(hasattr(cs, name) for name in declared)


def test_hertz_plane_peak_is_four_over_pi():
    """Requirement: the Hertz plane-strain peak over the mean pressure is 4/pi (Eq. 15), to the
    last bit but one (the two divisions round)."""
    c = cs.hertz_plane_contact(R=100.0, E=1000.0, nu=0.25, P=2.0)
    assert c.p_max / c.p_mean == pytest.approx(4 / math.pi, rel=4e-16)


def test_fields_take_and_return_arrays():
    """Requirement: a field at many points is one call with arrays, equal point by point to
    scalar calls, in the broadcast shape."""
    x = np.linspace(-2.0, 2.0, 7)
    z = np.array([[0.1], [0.5]])
    s = cs.mcewen_stress(a=1.0, p=1.0, x=x, z=z)
    assert s["sigma_z"].shape == (2, 7)
    for i in range(2):
        for j in range(7):
            one = cs.mcewen_stress(a=1.0, p=1.0, x=float(x[j]), z=float(z[i, 0]))
            assert isinstance(one["sigma_z"], float)
            assert s["sigma_z"][i, j] == one["sigma_z"]
    c = cs.hertz_plane_contact(R=1.0, E=1.0, nu=0.25, P=1e-3)
    p = cs.hertz_plane_pressure(c, x=np.array([0.0, 2 * c.contact_half_width_a]))
    assert p[0] == c.p_max and p[1] == 0.0


def cli_error(*args):
    r = subprocess.run([EXE, *args], capture_output=True, text=True)
    assert r.returncode == 2, r
    prefix = "contact-suite: error: "
    assert r.stderr.startswith(prefix), r.stderr
    return r.stderr[len(prefix):].strip()


def test_out_of_range_raises_value_error_with_the_cli_message():
    """Requirement: nu = 0.5 (and a load past Steuermann's range) raise ValueError with the
    message the command line prints."""
    with pytest.raises(ValueError) as e:
        cs.hertz_plane_contact(R=1.0, E=1.0, nu=0.5, P=1.0)
    assert str(e.value) == cli_error("oracle", "hertz-plane", "--R", "1", "--E", "1", "--nu",
                                     "0.5", "--load", "1")
    with pytest.raises(ValueError) as e:
        cs.steuermann_contact(b=1.0, r_e=1.0, P=1e6, E=1.0, nu=0.25)
    assert str(e.value) == cli_error("oracle", "steuermann", "--b", "1", "--re", "1", "--load",
                                     "1e6", "--E", "1", "--nu", "0.25")
    with pytest.raises(ValueError):
        cs.sadowsky_pressure(a=1.0, P=1.0, x=np.array([0.0, 1.0]))  # |x| = a: unbounded


def test_results_reader_values_are_the_files_bit_for_bit():
    """Requirement: the reader returns every case value and row verdict of results.json as the
    file holds it (Python's own json module, correctly rounded like the C++ reader, agrees to
    the bit)."""
    doc = cs.read_results(str(FIXTURE))
    raw = json.loads(FIXTURE.read_text())
    assert [c.id for c in doc.cases] == [c["id"] for c in raw["cases"]]
    assert [r.id for r in doc.rows] == [r["id"] for r in raw["rows"]]
    for case, rec in zip(doc.cases, raw["cases"]):
        assert case.status == rec["status"]
        assert case.wall_seconds == rec["wall_seconds"]
        for q in case.quantities:
            r = rec["quantities"][q.quantity]
            assert (q.value == r["value"]) or (math.isnan(q.value) and r["value"] is None)
            assert q.grade == r["grade"]
        assert case.to_dict()["quantities"].keys() == rec["quantities"].keys()
    for row, rec in zip(doc.rows, raw["rows"]):
        assert row.id == rec["id"]
        d = row.to_dict()
        for key in rec:  # every field the file holds, as the file holds it
            assert d[key] == rec[key], (row.id, key)
        assert row.grade == rec.get("grade")
        assert row.values == [rec["values"].get(m) for m in "CMF"]
    assert doc.row("H_p/Q4/AL/ss/sigma_c").grade == "e"
    assert doc.case("no/such/case") is None


def test_results_reader_refuses_a_bad_file(tmp_path):
    """Requirement: a file that is not a results file raises ValueError naming it."""
    bad = tmp_path / "results.json"
    bad.write_text('{"schema": "x"}')
    with pytest.raises(ValueError, match="results.json"):
        cs.read_results(str(bad))


def test_grading_functions():
    """Requirement: Eq. 46's bands, the converging verdict, Eq. 47 and the estimates, on values
    whose answers are known by hand."""
    assert [cs.grade(e) for e in (0.99, 1.0, -4.99, 5.0, 9.99, 10.0, math.nan)] == \
        ["e", "g", "g", "s", "s", "u", "u"]
    assert cs.error_percent(value=1.1, exact=1.0) == pytest.approx(10.0, rel=1e-14)
    assert np.allclose(cs.error_percent(value=np.array([1.0, 0.5]), exact=2.0), [-50.0, -75.0])
    assert cs.is_converging(error_c=4.0, error_m=2.0, error_f=1.0)
    assert not cs.is_converging(error_c=1.0, error_m=2.0, error_f=4.0)
    assert cs.is_diverging(value_c=2.0, value_m=2.4, value_f=3.0)
    assert not cs.is_diverging(value_c=2.0, value_m=2.4, value_f=2.5)
    v = cs.divergence_verdict(value_c=1.0, value_m=math.sqrt(2), value_f=2.0)
    assert v.eq47 and v.monotone and v.diverges and v.exponent == pytest.approx(0.5, rel=1e-14)
    # f = 1 + h^2 with h = 1, 1/2, 1/4: order 2, Richardson limit 1 (exact for a pure power).
    est = cs.error_estimate(value_c=2.0, value_m=1.25, value_f=1.0625)
    assert est.asymptotic and est.observed_order == pytest.approx(2.0, rel=1e-14)
    assert est.richardson == pytest.approx(1.0, rel=1e-14)
    assert cs.pair_orders(error_c=4.0, error_m=2.0, error_f=None) == [pytest.approx(1.0), None]


def test_grading_refuses_values_that_are_not_finite():
    """Requirement: a NaN or infinite error or value is a ValueError naming the argument, never a
    NaN verdict or a false 'asymptotic'; an exact value of 0 gives no percentage error."""
    for call in (lambda: cs.error_estimate(value_c=math.nan, value_m=1.0, value_f=0.5),
                 lambda: cs.is_converging(error_c=1.0, error_m=math.inf, error_f=0.5),
                 lambda: cs.divergence_verdict(value_c=1.0, value_m=2.0, value_f=math.nan),
                 lambda: cs.pair_orders(error_c=math.nan, error_m=2.0, error_f=1.0),
                 lambda: cs.trend(error_c=1.0, error_m=0.5, error_f=math.nan),
                 lambda: cs.observed_order(error_c=4.0, error_m=2.0, error_f=1.0,
                                           resolution_percent=math.nan)):
        with pytest.raises(ValueError, match="must be a finite number"):
            call()
    with pytest.raises(ValueError, match="value_c"):
        cs.error_estimate(value_c=math.nan, value_m=1.0, value_f=0.5)
    with pytest.raises(ValueError, match="non-zero exact"):
        cs.error_percent(value=1.0, exact=0.0)
    assert math.isnan(cs.error_percent(value=math.nan, exact=1.0))  # a value not available


def test_an_evaluation_too_large_raises_memory_error():
    """Requirement: a grid whose broadcast cannot be allocated (a row and a column of 200,000
    points: 298 GiB) raises MemoryError; it never crashes the interpreter."""
    with pytest.raises(MemoryError):
        cs.mcewen_stress(a=1.0, p=1.0, x=np.zeros(200000), z=np.zeros((200000, 1)))


def test_trend_and_order_of_a_value_read_between_nodes():
    """Requirement: the module's trend and observed order take the quantity's own resolution
    (half the node spacing for a value read between two nodes) and give no order from a mesh
    that does not resolve the quantity."""
    resolution = cs.node_read_resolution_percent(node_spacing=0.000764, exact=1.0047)
    assert resolution == pytest.approx(100 * 0.000382 / 1.0047, rel=1e-14)
    trend, floor, reason = cs.trend(error_c=0.12, error_m=0.10, error_f=0.09,
                                    resolution_percent=resolution)
    assert trend == "settled" and floor == resolution and "node spacing" in reason
    assert cs.trend(error_c=0.12, error_m=0.10, error_f=0.09)[0] == "converging"
    order, note = cs.observed_order(error_c=427.3, error_m=65.0, error_f=5.04)
    assert order is None and "not resolved" in note
