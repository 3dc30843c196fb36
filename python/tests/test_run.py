"""stormer.run: the scenes of the command line, their records as numpy arrays."""

import numpy as np
import pytest

import stormer


def test_the_acceptance_command():
    result = stormer.run("kepler", method="rk4", dt=0.01, t_end=10)
    summary = result["summary"]
    assert summary["method"] == "rk4" and summary["steps"] == 1000
    assert summary["evaluations"] == 4000
    assert summary["text"].startswith("rk4 on kepler: 1000 steps")
    assert summary["max_error"] < 1e-4


def test_arrays_have_the_shapes_of_the_csv():
    result = stormer.run("pendulum", method="rk4", dt=0.01, t_end=1.0, every=1)
    t, y, energy = result["t"], result["y"], result["energy"]
    assert result["components"] == ["theta", "omega"]
    assert t.dtype == np.float64 and t.shape == (101,)
    assert y.shape == (101, 2) and energy.shape == (101,)
    assert t[0] == 0.0 and t[-1] == pytest.approx(1.0)
    assert y[0, 0] == pytest.approx(np.pi / 4)
    assert np.max(np.abs(energy - energy[0])) < 1e-8


def test_save_at_gives_exactly_those_times():
    times = np.linspace(0.0, 6.0, 7)
    result = stormer.run("kepler", method="dop853", rtol=1e-10, save_at=times)
    assert np.array_equal(result["t"], times)


def test_scene_numbers_replace_the_files():
    near = stormer.run("free-kick", alpha=20.0)
    far = stormer.run("free-kick", alpha=40.0)
    assert near["summary"]["stop"] and far["summary"]["stop"]
    assert near["t"][-1] < far["t"][-1]


def test_scene_without_energy_has_none():
    result = stormer.run("damped-oscillator", method="rk4", dt=0.01, t_end=1.0)
    assert result["energy"] is None and result["summary"]["energy_drift"] is None
    # and its exact solution is known: the deviation from it is measured
    assert result["summary"]["max_error"] < 1e-5


def test_split_and_corrector_on_the_outer_solar_system():
    plain = stormer.run("outer-solar-system", method="wisdom_holman", split="kepler-jacobi", t_end=10000)
    corrected = stormer.run(
        "outer-solar-system", method="wisdom_holman", split="kepler-jacobi", corrector=11, t_end=10000
    )
    assert "corrector 11" in corrected["summary"]["text"]
    assert corrected["summary"]["energy_drift"] < plain["summary"]["energy_drift"]


def test_a_scene_file(tmp_path):
    path = tmp_path / "osc.toml"
    path.write_text(
        'model = "harmonic"\n[parameters]\nw0 = 1.0\n[initial]\nx = 1.0\nv = 0.0\n[run]\nmethod = "rk4"\ndt = 0.01\nt_end = 1.0\nevery = 1\n'
    )
    result = stormer.run(str(path))
    assert result["t"].shape == (101,)
    assert result["y"][-1, 0] == pytest.approx(np.cos(1.0), abs=1e-8)


def test_unknown_method_is_a_value_error_with_suggestions():
    with pytest.raises(ValueError, match="unknown method 'rk5'; did you mean"):
        stormer.run("kepler", method="rk5")


def test_unknown_scene_and_number():
    with pytest.raises(ValueError, match="nosuchscene"):
        stormer.run("nosuchscene")
    with pytest.raises(ValueError, match="invalid scene number: unknown key 'spinn': did you mean 'parameters.spin'"):
        stormer.run("free-kick", spinn=3.0)
    with pytest.raises(ValueError, match="give the whole key"):
        stormer.run("outer-solar-system", mass=1.0)
    # a whole key, dots included
    assert stormer.run("free-kick", **{"initial.alpha": 30.0})["t"][-1] == stormer.run("free-kick", alpha=30.0)["t"][-1]


def test_bad_values_are_value_errors():
    with pytest.raises(ValueError, match="--dt"):
        stormer.run("kepler", dt=-1.0)
    with pytest.raises(ValueError, match="--dt"):
        stormer.run("kepler", dt=float("nan"))
    with pytest.raises(ValueError, match="save-at"):
        stormer.run("kepler", save_at=[0.0, float("nan")])
    with pytest.raises(ValueError, match="must go up"):
        stormer.run("free-kick", alpha=-10.0)


def test_wrong_types_are_type_errors():
    with pytest.raises(TypeError):
        stormer.run("kepler", method=3)
    with pytest.raises(TypeError):
        stormer.run("kepler", dt="small")
    with pytest.raises(TypeError):
        stormer.run("free-kick", alpha="steep")


def test_a_splitting_on_a_scene_with_friction_is_refused():
    with pytest.raises(ValueError):
        stormer.run("damped-oscillator", method="stormer_verlet_dkd")


def test_a_run_that_fails_keeps_its_records():
    with pytest.raises(stormer.RunError, match="max-steps") as failed:
        stormer.run("kepler", method="dopri5", rtol=1e-12, max_steps=10, every=1)
    partial = failed.value.partial
    assert partial["t"].shape[0] == 11 and partial["y"].shape == (11, len(partial["components"]))
    assert partial["summary"]["steps"] == 10


def test_a_fixed_step_run_over_the_limit_is_refused_before_it_starts():
    with pytest.raises(ValueError, match="max-steps"):
        stormer.run("kepler", method="rk4", dt=0.01, t_end=100.0, max_steps=10)
