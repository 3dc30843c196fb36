"""stormer.integrate (a Python right-hand side) and stormer.ensemble."""

import numpy as np
import pytest

import stormer


def oscillator(t, y):
    return np.array([y[1], -y[0]])


def test_a_python_rhs_with_a_catalog_method():
    result = stormer.integrate(oscillator, [1.0, 0.0], 2 * np.pi, method="rk4", dt=0.01)
    assert result["y"].shape == (result["t"].shape[0], 2)
    assert np.allclose(result["y"][-1], [1.0, 0.0], atol=1e-8)
    assert result["summary"]["evaluations"] == 4 * result["summary"]["steps"]


def test_adaptive_steps_and_save_at():
    times = np.linspace(0, 3, 4)
    result = stormer.integrate(oscillator, [1.0, 0.0], 3.0, rtol=1e-10, save_at=times)
    assert np.array_equal(result["t"], times)
    assert np.allclose(result["y"][:, 0], np.cos(times), atol=1e-8)


def test_a_method_as_data_on_a_python_rhs():
    heun = stormer.method(name="my_heun", order=2, c=[0, 1], a=[[0, 0], [1, 0]], b=["1/2", "1/2"])
    result = stormer.integrate(oscillator, [1.0, 0.0], 1.0, method=heun, dt=0.001)
    assert result["y"][-1, 0] == pytest.approx(np.cos(1.0), abs=1e-6)


def test_lists_and_ints_are_accepted_from_the_callable():
    result = stormer.integrate(lambda t, y: [1, 0], [0, 0], 1.0, method="euler", dt=0.5)
    assert result["y"][-1, 0] == pytest.approx(1.0)


def test_a_callable_that_raises_raises_its_exception():
    calls = []

    def fails(t, y):
        calls.append(t)
        if len(calls) > 3:
            raise KeyError("the model broke")
        return -y

    with pytest.raises(KeyError, match="the model broke"):
        stormer.integrate(fails, [1.0], 10.0, method="rk4", dt=0.1)
    assert len(calls) == 4  # stopped at the first exception


def test_a_callable_returning_the_wrong_shape_or_type():
    with pytest.raises(ValueError, match="returned 3 values at t = 0 for a state of 2"):
        stormer.integrate(lambda t, y: [1.0, 2.0, 3.0], [0.0, 0.0], 1.0, method="rk4", dt=0.1)
    with pytest.raises(TypeError, match="must return a 1-D array"):
        stormer.integrate(lambda t, y: "fast", [0.0, 0.0], 1.0, method="rk4", dt=0.1)
    with pytest.raises(TypeError, match="must return a 1-D array"):
        stormer.integrate(lambda t, y: None, [0.0, 0.0], 1.0, method="rk4", dt=0.1)


def test_bad_initial_states_and_arguments():
    with pytest.raises(ValueError, match=r"y0 must be finite: y0\[1\] = nan"):
        stormer.integrate(oscillator, [1.0, np.nan], 1.0, method="rk4", dt=0.1)
    with pytest.raises(ValueError, match="1-D"):
        stormer.integrate(oscillator, [[1.0, 0.0]], 1.0, method="rk4", dt=0.1)
    with pytest.raises(TypeError, match="array of numbers"):
        stormer.integrate(oscillator, ["a", "b"], 1.0, method="rk4", dt=0.1)
    with pytest.raises(TypeError, match="callable"):
        stormer.integrate(42, [1.0, 0.0], 1.0, method="rk4", dt=0.1)
    with pytest.raises(ValueError, match="did you mean"):
        stormer.integrate(oscillator, [1.0, 0.0], 1.0, method="rk5", dt=0.1)
    with pytest.raises(ValueError, match="dt="):
        stormer.integrate(oscillator, [1.0, 0.0], 1.0, method="rk4")
    with pytest.raises(ValueError, match="every"):
        stormer.integrate(oscillator, [1.0, 0.0], 1.0, method="rk4", dt=0.1, every=0)


def test_a_splitting_needs_a_hamiltonian_problem():
    with pytest.raises(ValueError):
        stormer.integrate(oscillator, [1.0, 0.0], 1.0, method="stormer_verlet_dkd", dt=0.1)


def test_ensemble_returns_one_structured_array():
    table = stormer.ensemble("free-kick", {"alpha": (10, 50, 5), "spin": (0, 20, 3)})
    assert table.shape == (15,)
    assert table.dtype.names[:2] == ("initial.alpha", "parameters.spin")
    assert {"t", "x", "energy_error", "steps", "evaluations", "stopped", "failure"} <= set(table.dtype.names)
    assert np.all(table["stopped"]) and np.all(table["failure"] == "")
    # the first axis varies slowest
    assert np.array_equal(table["initial.alpha"][:3], [10.0, 10.0, 10.0])
    assert np.array_equal(table["parameters.spin"][:3], [0.0, 10.0, 20.0])


def test_ensemble_members_are_the_runs_of_the_scene():
    table = stormer.ensemble("free-kick", {"alpha": (20, 40, 3)})
    for row in table:
        alone = stormer.run("free-kick", alpha=float(row["initial.alpha"]))
        assert alone["t"][-1] == row["t"]


def test_ensemble_same_rows_on_one_thread_or_two():
    one = stormer.ensemble("free-kick", {"alpha": (10, 50, 9), "spin": (0, 20, 9)}, jobs=1)
    two = stormer.ensemble("free-kick", {"alpha": (10, 50, 9), "spin": (0, 20, 9)}, jobs=2)
    assert one.tobytes() == two.tobytes()


def test_ensemble_bad_input():
    with pytest.raises(ValueError, match="unknown"):
        stormer.ensemble("free-kick", {"nothing": (0, 1, 2)})
    with pytest.raises(ValueError, match="refused"):
        stormer.ensemble("free-kick", {"alpha": (-10, 30, 5)})
    with pytest.raises(TypeError, match="start, end, count"):
        stormer.ensemble("free-kick", {"alpha": (10, 50)})
    with pytest.raises(TypeError, match="non-empty dict"):
        stormer.ensemble("free-kick", {})
    with pytest.raises(ValueError, match="did you mean"):
        stormer.ensemble("free-kick", {"alpha": (10, 50, 3)}, method="rk5")
    with pytest.raises(ValueError, match="--jobs"):
        stormer.ensemble("free-kick", {"alpha": (10, 50, 3)}, jobs=0)


def test_ensemble_releases_the_interpreter_lock():
    """A Python thread keeps running while the ensemble runs."""
    import threading
    import time

    ticks = []
    done = threading.Event()

    def ticker():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    thread = threading.Thread(target=ticker)
    thread.start()
    try:
        start = time.perf_counter()
        stormer.ensemble("free-kick", {"alpha": (10, 50, 41), "spin": (0, 20, 41)})
        end = time.perf_counter()
    finally:
        done.set()
        thread.join()
    during = [t for t in ticks if start < t < end]
    assert end - start > 0.01 and len(during) > 3


def test_ctrl_c_in_a_python_rhs_stops_the_run():
    def interrupted(t, y):
        if t > 0.5:
            raise KeyboardInterrupt
        return -y

    with pytest.raises(KeyboardInterrupt):
        stormer.integrate(interrupted, [1.0], 10.0, method="rk4", dt=0.1)
