"""Bad input to the simulate: a ValueError naming the parameter, the value and what is allowed
(the command line: one line on stderr, exit 2), never another exception, a hang or a
silent NaN. Reproducers of defects a fuzzing audit found; each must stay fixed (the C++
side of several is in cpp/tests/test_hardening.cpp)."""


import pytest



def test_supports_and_loads_must_be_arrays_of_tables():
    from kresling.simulate import load_problem
    problem = {"pattern": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "panels": [[0, 1, 2]]},
               "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0},
               "support": None, "load": [{"node": 2, "force": [0.0, 1.0, 0.0]}],
               "analysis": {"method": "force_control", "steps": 2}}
    with pytest.raises(ValueError, match=r"^problem: .*'support' = None is invalid: must be an "
                                         r"array of tables"):
        load_problem(problem)


def test_a_model_the_problem_cannot_build_names_the_problem_key():
    from kresling.simulate import simulate
    problem = {"pattern": {"vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]],
                           "panels": [[0, 1, 2, 3]]},
               "material": {"calibration": "auto", "E": 1000.0, "nu": 0.0, "thickness": 0.25},
               "support": [{"nodes": [0, 1], "fix": "xyz"}, {"node": 3, "fix": "z"}],
               "load": [{"node": 2, "force": [0.0, 0.0, 0.01]}],
               "analysis": {"method": "force_control", "steps": 2}}
    with pytest.raises(ValueError, match=r"^problem: \[material\] key 'nu': poisson_ratio = 0 is "
                                         r"invalid"):
        simulate(problem)
