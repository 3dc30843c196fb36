"""stormer.Simulation: bodies and charged particles built in Python."""

import numpy as np
import pytest

import stormer

G_SUN = 2.95912208286e-4


def outer_solar_system():
    sim = stormer.Simulation.from_scene("outer-solar-system")
    sim.method, sim.split = "wisdom_holman", "kepler-jacobi"
    return sim


def test_from_scene_reads_the_bodies():
    sim = stormer.Simulation.from_scene("outer-solar-system")
    assert sim.n == 4 and sim.G == G_SUN and sim.dt == 10.0
    assert sim.m[1] == pytest.approx(0.000954786104043)
    assert np.array_equal(sim.x[1], [-3.5023653, -3.8169847, -1.5507963])
    assert np.array_equal(sim.v[1], [0.00565429, -0.00412490, -0.00190589])


def test_integrate_matches_the_same_run_of_the_scene():
    sim = outer_solar_system()
    sim.integrate(1000.0)
    same = stormer.run("outer-solar-system", method="wisdom_holman", split="kepler-jacobi", t_end=1000.0)
    assert sim.t == 1000.0
    n = sim.n
    assert np.allclose(sim.x.ravel(), same["y"][-1, : 3 * n], rtol=0, atol=1e-12)


def test_integrate_in_pieces_and_the_energy_stays():
    sim = outer_solar_system()
    e0 = sim.energy()
    for t in (1000.0, 2000.0, 2005.0):
        summary = sim.integrate(t)
        assert sim.t == t
    assert summary["steps"] == 1
    assert abs((sim.energy() - e0) / e0) < 1e-8


def test_corrector_and_every_catalog_method():
    sim = outer_solar_system()
    sim.corrector = 11
    assert "corrector 11" in sim.integrate(1000.0)["text"]
    plain = stormer.Simulation.from_scene("outer-solar-system", method="rk4", split=None)
    plain.integrate(100.0)
    assert plain.t == 100.0


def test_state_is_writable_between_calls():
    sim = outer_solar_system()
    x0, v0 = sim.x, sim.v
    sim.integrate(500.0)
    sim.x, sim.v, sim.t = x0, v0, 0.0
    sim.integrate(500.0)
    again = outer_solar_system()
    again.integrate(500.0)
    assert np.array_equal(sim.x, again.x)
    state = sim.state
    assert state.shape == (24,)
    sim.state = state
    assert np.array_equal(sim.x, again.x)


def test_orbital_elements_as_rebound_adds_them():
    sim = stormer.Simulation(G=1.0)
    sim.add(m=1.0)
    sim.add(m=1e-3, a=1.0, e=0.0)
    # a circular orbit of radius 1 about the star at rest, speed sqrt(G (m0 + m1) / a)
    assert np.linalg.norm(sim.x[1]) == pytest.approx(1.0)
    assert np.linalg.norm(sim.v[1]) == pytest.approx(np.sqrt(1.001))
    sim.add(m=1e-3, a=2.0, e=0.1, inc=0.2, Omega=0.3, omega=0.4, f=0.5, name="outer")
    assert sim.n == 3 and abs(sim.x[2, 2]) > 0


def test_orbits_run_in_the_kepler_split():
    sim = stormer.Simulation(G=1.0, method="wisdom_holman", dt=0.01, split="kepler-jacobi")
    sim.add(m=1.0)
    sim.add(m=1e-3, a=1.0, e=0.1)
    e0 = sim.energy()
    sim.integrate(2 * np.pi * 10)
    assert abs((sim.energy() - e0) / e0) < 1e-6


def test_charged_particles():
    sim = stormer.Simulation("charged-particles", omega=[0.0, 0.0, 1.0], method="boris", dt=0.01)
    sim.add(charge=1.0, x=[1.0, 0.0, 0.0], v=[0.0, 1.0, 0.0])
    sim.integrate(2 * np.pi)
    # one gyration in a uniform field of strength 1: back where it started
    assert np.linalg.norm(sim.v[0]) == pytest.approx(1.0, abs=1e-12)
    assert sim.t == pytest.approx(2 * np.pi)


def test_bad_arrays_are_named():
    sim = outer_solar_system()
    with pytest.raises(ValueError, match=r"x must have shape \(4, 3\), got \(3, 3\)"):
        sim.x = np.zeros((3, 3))
    with pytest.raises(ValueError, match=r"v\[2, 1\] = nan is not finite"):
        v = sim.v
        v[2, 1] = np.nan
        sim.v = v
    with pytest.raises(TypeError, match="float64"):
        sim.x = np.array([["a", "b", "c"]] * 4)
    with pytest.raises(ValueError, match="masses must be > 0"):
        sim.m = [1.0, 0.0, 1.0, 1.0]
    with pytest.raises(ValueError, match="shape"):
        sim.state = np.zeros(5)


def test_bad_bodies_are_refused():
    sim = stormer.Simulation(G=1.0)
    with pytest.raises(ValueError, match="no bodies"):
        sim.integrate(1.0)
    with pytest.raises(ValueError, match="x must have shape"):
        sim.add(m=1.0, x=[0.0, 0.0])
    with pytest.raises(ValueError, match="not finite"):
        sim.add(m=1.0, x=[0.0, np.nan, 0.0])
    with pytest.raises(ValueError, match="mass must be > 0"):
        sim.add(m=-1.0)
    sim.add(m=1.0)
    with pytest.raises(ValueError, match="not both"):
        sim.add(m=1e-3, x=[1.0, 0.0, 0.0], a=1.0, e=0.0)
    with pytest.raises(TypeError, match="unknown argument"):
        sim.add(m=1e-3, semi_major=1.0)
    with pytest.raises(ValueError, match="already"):
        sim.add(m=1e-3, x=[1.0, 0.0, 0.0], name="body0")
    # the library refuses an eccentricity of a bound orbit >= 1 with a > 0
    with pytest.raises(ValueError):
        sim.add(m=1e-3, a=1.0, e=1.5)
    assert sim.n == 1


def test_bad_settings_are_refused_at_integrate():
    sim = outer_solar_system()
    sim.method = "rk5"
    with pytest.raises(ValueError, match="did you mean"):
        sim.integrate(100.0)
    sim.method, sim.split = "rk4", "kepler-sideways"
    with pytest.raises(ValueError):
        sim.integrate(100.0)
    with pytest.raises(ValueError):
        stormer.Simulation("fluid")


def canonical(d):
    return np.block([[np.zeros((d, d)), np.eye(d)], [-np.eye(d), np.zeros((d, d))]])


def test_step_jacobian_is_symplectic_for_symplectic_methods():
    S = canonical(12)
    verlet = stormer.step_jacobian("outer-solar-system", "stormer_verlet_dkd", 10.0)
    euler = stormer.step_jacobian("outer-solar-system", "euler", 10.0)
    assert verlet.shape == (24, 24)
    assert np.max(np.abs(verlet.T @ S @ verlet - S)) < 1e-9
    assert np.max(np.abs(euler.T @ S @ euler - S)) > 1e-5
    # d q_new / d p = h / m for explicit Euler, exactly
    assert euler[3, 15] == pytest.approx(10.0 / 0.000954786104043)


def test_step_jacobian_agrees_with_finite_differences():
    sim = stormer.Simulation(G=1.0, method="rk4", dt=0.1)
    sim.add(m=1.0)
    sim.add(m=1e-3, a=1.0, e=0.2)
    J = sim.step_jacobian()
    y0 = sim.state

    def step(y):
        other = stormer.Simulation(G=1.0, method="rk4", dt=0.1)
        other.add(m=1.0, x=[0.0, 0.0, 0.0])
        other.add(m=1e-3, x=[1.0, 0.0, 0.0])
        other.state = y
        other.integrate(0.1)
        return other.state

    h = 1e-6
    for j in (3, 4, 10):
        e = np.zeros_like(y0)
        e[j] = h
        column = (step(y0 + e) - step(y0 - e)) / (2 * h)
        assert np.allclose(J[:, j], column, rtol=1e-5, atol=1e-6)


def test_step_jacobian_refusals():
    with pytest.raises(ValueError, match="n-body"):
        stormer.step_jacobian("pendulum", "rk4", 0.1)
    with pytest.raises(ValueError, match="did you mean"):
        stormer.step_jacobian("outer-solar-system", "rk5", 10.0)
    with pytest.raises(ValueError, match="dt"):
        stormer.step_jacobian("outer-solar-system", "rk4", float("nan"))
    with pytest.raises(ValueError, match="split"):
        stormer.step_jacobian("two-planets", "rk4", 1.0)
