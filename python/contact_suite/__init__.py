"""contact-suite: exact solutions of frictionless and frictional contact problems (the oracles),
the reader of results.json, the grading rules of the study (Eq. 46, convergence, divergence,
Eq. 47), and the solver protocol's files (docs/solver-protocol.md): the reader of a case
directory into NumPy arrays and the writer of the results an external code returns.

    import contact_suite as cs
    c = cs.hertz_plane_contact(R=100.0, E=1000.0, nu=0.25, P=2.0)
    c.p_max / c.p_mean                           # 4/pi (study Eq. 15)

    case = cs.read_case("case")                  # an adapter: read, solve, write back
    u = my_solver(case.nodes, case.bodies[0].elements, ...)
    cs.write_results("case", nodes=case.deformable_nodes, displacement=u, case=case)

Out-of-range parameters raise ValueError with the message the command line prints. The oracles,
results reader and grading functions are compiled (the C++ code the command runs, module
contact_suite._core); the case-directory reader and the results writer are plain Python.
"""
from contact_suite._core import *  # noqa: F401,F403 (the compiled oracles, reader, grading)
from contact_suite._core import __version__  # noqa: F401
from contact_suite.case_directory import (  # noqa: F401
    Body, Case, Constraint, ContactPair, LoadControl, RigidProfile, read_case)
from contact_suite.result_files import write_results  # noqa: F401
