"""stormer from Python: ODE integration where methods are data.

The catalog of methods, their verification, the scenes of the ``stormer`` command line,
n-body and charged-particle simulations built in Python, your own right-hand side as a
Python callable, your own method as data, and ensembles on all cores. Numbers go in and
come out as numpy arrays; every refusal of an input is a ``ValueError`` (or a
``TypeError`` for a wrong type) carrying the library's own message.

>>> import stormer
>>> r = stormer.run("kepler", method="rk4", dt=0.01, t_end=10)
>>> r["y"].shape[1], r["summary"]["method"]
(4, 'rk4')

docs/python.md gives the whole API, with its costs.
"""

from __future__ import annotations

import json
import math
from typing import Any, Callable, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _stormer
from ._stormer import Method

__all__ = [
    "Method",
    "RunError",
    "Simulation",
    "ensemble",
    "integrate",
    "method",
    "methods",
    "run",
    "step_jacobian",
    "verify",
]

MethodArg = Union[str, Method, None]


class RunError(RuntimeError):
    """A run that failed on the way (it diverged, reached its step limit).

    Its message is the library's; ``partial`` holds what was computed up to there, in the
    same dict as a finished run returns, so nothing is lost.
    """

    def __init__(self, message: str, partial: Dict[str, Any]):
        super().__init__(message)
        self.partial = partial


def methods() -> List[Dict[str, Any]]:
    """The catalog: one dict per method, the objects of ``stormer methods --json``.

    Keys: ``name``, ``family``, ``order``, ``stages``, ``explicit``, ``embedded_order``,
    ``fsal``, ``symplectic``, ``symmetric``, ``dense_order``, ``aliases``.
    """
    return json.loads(_stormer.methods_json())


def verify(method: Union[str, Method]) -> Dict[str, Any]:
    """Check a method: what ``stormer verify METHOD --format json`` prints, as a dict.

    ``method`` is a catalog name or alias, a path to a TOML method file, or a
    :class:`Method` (from :func:`method`). Besides the report's keys (flags, every order
    condition with its residual, the measured order, symplecticity ``J^T S J = S`` and
    reversibility), ``contradictions`` lists what the measurements contradict among the
    method's declarations (empty for a sound method: the command exits 1 otherwise).
    """
    if isinstance(method, Method):
        text, contradictions = method.verify_json()
    elif isinstance(method, str):
        text, contradictions = _stormer.verify_json(method)
    else:
        raise TypeError(f"method must be a name (str) or a stormer.Method, got {type(method).__name__}")
    report = json.loads(text)
    report["contradictions"] = list(contradictions)
    return report


def _toml_value(value: Any) -> str:
    """A number, a string or a (nested) list as TOML; floats exactly (their repr)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        v = float(value)
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    raise TypeError(f"cannot write {type(value).__name__} {value!r} as a number or a list of numbers")


def method(
    toml: Optional[str] = None,
    *,
    name: str = "python_method",
    order: Optional[int] = None,
    a: Optional[Sequence[Sequence[Union[float, str]]]] = None,
    b: Optional[Sequence[Union[float, str]]] = None,
    c: Optional[Sequence[Union[float, str]]] = None,
    b_hat: Optional[Sequence[Union[float, str]]] = None,
    embedded_order: Optional[int] = None,
    drift: Optional[Sequence[Union[float, str]]] = None,
    kick: Optional[Sequence[Union[float, str]]] = None,
    gamma: Optional[Sequence[Union[float, str]]] = None,
    family: Optional[str] = None,
) -> Method:
    """Your own method as data, checked by the same order conditions as in Rust.

    Either ``toml``, the text of a method file in the catalog's format, or the
    coefficients as lists: a Butcher tableau (``a``, ``b``, ``c``, optionally ``b_hat`` and
    ``embedded_order``), a splitting (``drift`` and ``kick``) or a composition (``gamma``),
    with its ``name`` and declared ``order``. Coefficients are numbers or exact fractions
    as strings (``"1/2"``). A method whose coefficients miss its declared order is refused
    with a ``ValueError`` naming the failing condition, as the command line refuses the
    file.

    >>> heun = stormer.method(name="heun", order=2, c=[0, 1], a=[[0, 0], [1, 0]], b=["1/2", "1/2"])
    """
    if toml is not None:
        if not isinstance(toml, str):
            raise TypeError(f"toml must be the text of a method file (str), got {type(toml).__name__}")
        return Method.from_toml(toml, "Python")
    if order is None:
        raise ValueError("give the method's declared order (order=...), or its TOML text")
    lines = [f"name = {_toml_value(name)}", f"order = {_toml_value(order)}"]
    if family is not None:
        lines.append(f"family = {_toml_value(family)}")
    fields = {
        "c": c,
        "a": a,
        "b": b,
        "b_hat": b_hat,
        "embedded_order": embedded_order,
        "drift": drift,
        "kick": kick,
        "gamma": gamma,
    }
    for key, value in fields.items():
        if value is not None:
            if key != "embedded_order":
                value = _coefficients(value)
            lines.append(f"{key} = {_toml_value(value)}")
    return Method.from_toml("\n".join(lines) + "\n", "Python")


def _coefficients(value: Any) -> Any:
    """Coefficients as the file format writes them: strings (exact fractions or numbers)."""
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return [_coefficients(v) for v in value]
    if isinstance(value, str):
        return value
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"a coefficient is a number or a fraction as a string ('1/2'), got {value!r}")
    return repr(float(value))


def _records(result: Dict[str, Any]) -> Dict[str, Any]:
    """A run's dict, or :class:`RunError` with it when the run failed on the way."""
    failure = result.pop("failure")
    if failure is not None:
        raise RunError(failure, result)
    return result


def run(
    scene: str,
    method: MethodArg = None,
    dt: Optional[float] = None,
    t_end: Optional[float] = None,
    save_at: Optional[Iterable[float]] = None,
    *,
    every: Optional[int] = None,
    split: Optional[str] = None,
    corrector: Optional[int] = None,
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    compensated: bool = False,
    max_steps: Optional[int] = None,
    **scene_numbers: float,
) -> Dict[str, Any]:
    """Run a scene as ``stormer run`` does; its records come back as numpy arrays.

    ``scene`` is a built-in scene (``pendulum``, ``kepler``, ``outer-solar-system``, ...) or
    a path to a scene file. Every argument left out is the scene file's: ``method`` (a
    name, alias, method file or :class:`Method`), ``dt``, ``t_end``, ``every`` (a record
    every N steps); ``save_at`` gives the output times instead; ``split``
    (``"kepler-jacobi"``, ``"kepler-democratic"``, ``"none"``), ``corrector`` (3, 5, 7, 11 or
    17), ``rtol``/``atol`` (adaptive steps), ``compensated`` and ``max_steps`` are the
    command line's options. Any other keyword replaces a number of the scene file by its
    key, as ``stormer ensemble --vary`` names it (``alpha=30`` for ``initial.alpha``).

    Returns a dict: ``t`` (n,), ``y`` (n, k), ``energy`` (n,) or None, ``components`` (the
    k names) and ``summary`` (steps, evaluations, energy drift, error against the exact
    solution, the summary line). Raises ``ValueError`` for a bad argument (an unknown
    method with the "did you mean" suggestion), :class:`RunError` for a run that failed on
    the way (with what it computed).
    """
    times = None if save_at is None else [float(t) for t in np.asarray(save_at, dtype=float).ravel()]
    result = _stormer.run(
        scene=scene,
        method=method,
        dt=dt,
        t_end=t_end,
        every=every,
        save_at=times,
        split=split,
        corrector=corrector,
        rtol=rtol,
        atol=atol,
        compensated=compensated,
        max_steps=max_steps,
        numbers=dict(scene_numbers) or None,
    )
    return _records(result)


def step_jacobian(scene: str, method: Union[str, Method], dt: float) -> np.ndarray:
    """The exact Jacobian ``d y1 / d y0`` of one step of ``method`` with step ``dt`` from an
    n-body scene's initial state, computed by running the step on dual numbers (exact up
    to rounding: no finite differences). The state is the positions then the momenta, so
    a symplectic step satisfies ``J.T @ S @ J == S`` with ``S = [[0, I], [-I, 0]]`` to
    round-off. Unsplit n-body scenes (a :class:`Simulation`: its ``step_jacobian()``).
    """
    return _stormer.step_jacobian(method, float(dt), scene=scene)


def integrate(
    f: Callable[[float, np.ndarray], Any],
    y0: Any,
    t_end: float,
    *,
    method: MethodArg = None,
    dt: Optional[float] = None,
    t0: float = 0.0,
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    every: int = 1,
    save_at: Optional[Iterable[float]] = None,
    max_steps: Optional[int] = None,
) -> Dict[str, Any]:
    """Integrate your own ``y' = f(t, y)`` from ``(t0, y0)`` to ``t_end``.

    ``f`` takes the time and the state (a 1-D float64 array) and returns the derivative
    (any 1-D sequence of the state's length). Any Runge-Kutta method of the catalog or of
    your own (:func:`method`) runs it, at fixed steps ``dt`` or adaptive steps within
    ``rtol``/``atol`` (methods with an embedded pair; the default method is ``dopri5``).
    Each evaluation calls into the interpreter: about 1 us each, against a few ns for the
    built-in models (docs/python.md); an exception raised by ``f`` is raised from here.

    Returns ``t`` (n,), ``y`` (n, len(y0)) and ``summary`` (steps, evaluations).
    """
    y = _state_vector(y0, "y0")
    times = None if save_at is None else [float(t) for t in np.asarray(save_at, dtype=float).ravel()]
    result = _stormer.integrate(
        f, y.tolist(), float(t_end), method=method, dt=dt, t0=float(t0), rtol=rtol, atol=atol,
        every=every, save_at=times, max_steps=max_steps,
    )
    return _records(result)


def _state_vector(value: Any, what: str) -> np.ndarray:
    """A 1-D float array, finite, or the error naming what is wrong."""
    try:
        y = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{what} must be an array of numbers: {e}") from None
    if y.ndim != 1:
        raise ValueError(f"{what} must be 1-D, got shape {y.shape}")
    bad = np.flatnonzero(~np.isfinite(y))
    if bad.size:
        raise ValueError(f"{what} must be finite: {what}[{bad[0]}] = {y[bad[0]]}")
    return y


def ensemble(
    scene: str,
    vary: Mapping[str, Tuple[float, float, int]],
    *,
    method: Optional[str] = None,
    dt: Optional[float] = None,
    t_end: Optional[float] = None,
    jobs: Optional[int] = None,
) -> np.ndarray:
    """Run a scene for every combination of values of some of its numbers, on all cores.

    ``vary`` maps a number of the scene file (its key, or its last parts: ``alpha`` for
    ``initial.alpha``) to ``(start, end, count)``: ``count`` values evenly from ``start`` to
    ``end``; with several, their grid, the first varying slowest (``stormer ensemble
    --vary``). The members run on ``jobs`` worker threads (default: one per core) with the
    interpreter's lock released.

    Returns one structured array, one row per member: the varied numbers, ``t`` (where the
    run ended: the free kick's landing), the state's components, ``energy_error`` (scenes
    with an energy), ``steps``, ``evaluations``, ``stopped`` (the scene's stop event ended
    the run) and ``failure`` ('' or why the member failed; its numbers are then NaN).
    """
    if not isinstance(vary, Mapping) or not vary:
        raise TypeError("vary must be a non-empty dict {name: (start, end, count)}")
    axes = []
    for key, spec in vary.items():
        try:
            start, end, count = spec
        except (TypeError, ValueError):
            raise TypeError(f"vary[{key!r}] must be (start, end, count), got {spec!r}") from None
        if isinstance(count, float) and not count.is_integer():
            raise TypeError(f"vary[{key!r}]: count must be a whole number, got {count!r}")
        if int(count) < 0:
            raise ValueError(f"vary[{key!r}]: count must be >= 1, got {count}")
        axes.append((str(key), float(start), float(end), int(count)))
    table = _stormer.ensemble(scene, axes, method=method, dt=dt, t_end=t_end, jobs=jobs)
    columns = table["columns"]
    failures = ["" if f is None else f for f in table["failures"]]
    width = max([1] + [len(f) for f in failures])
    dtype = [(c, np.float64) for c in columns] + [("stopped", np.bool_), ("failure", f"U{width}")]
    out = np.empty(len(failures), dtype=dtype)
    values = table["values"]
    for k, c in enumerate(columns):
        out[c] = values[:, k]
    out["stopped"] = table["stopped"]
    out["failure"] = failures
    return out


_ELEMENTS = ("a", "e", "inc", "Omega", "omega", "M", "f")


class Simulation:
    """Bodies (n-body gravity) or charged particles built in Python, integrated by any
    method of the catalog, in the Kepler split with its correctors, their state readable
    and writable as numpy arrays between calls (as ``rebound.Simulation``).

    >>> sim = stormer.Simulation(G=1.0)
    >>> sim.add(m=1.0)
    >>> sim.add(m=1e-3, a=1.0, e=0.1)
    >>> sim.method, sim.split, sim.dt = "wisdom_holman", "kepler-jacobi", 0.01
    >>> sim.integrate(10.0)

    ``model`` is ``"n-body"`` (``G``) or ``"charged-particles"`` with its fields as
    keywords (``omega``, ``B``, ``E``, ``mu``: docs/charged-particles.md). Positions ``x`` and
    velocities ``v`` are (n, 3) arrays, masses ``m`` (n,); ``t`` is the time.
    """

    def __init__(
        self,
        model: str = "n-body",
        *,
        G: float = 1.0,
        method: MethodArg = "velocity_verlet_kdk",
        dt: float = 0.01,
        split: Optional[str] = None,
        corrector: Optional[int] = None,
        elements: str = "jacobi",
        **parameters: Any,
    ):
        if model not in ("n-body", "charged-particles"):
            raise ValueError(f"model is 'n-body' or 'charged-particles', got {model!r}")
        if model == "n-body" and parameters:
            raise TypeError(f"an n-body Simulation takes G, not {', '.join(sorted(parameters))}")
        self.model = model
        self.G = float(G)
        self.method = method
        self.dt = dt
        self.split = split
        self.corrector = corrector
        self.elements = elements
        self.parameters = dict(parameters)
        self.t = 0.0
        self._names: List[str] = []
        self._m = np.zeros(0)
        self._q = np.zeros(0)
        self._x = np.zeros((0, 3))
        self._v = np.zeros((0, 3))

    @property
    def n(self) -> int:
        """The number of bodies or particles."""
        return len(self._names)

    @property
    def m(self) -> np.ndarray:
        """Masses, (n,) (a copy: set the whole array to change them)."""
        return self._m.copy()

    @m.setter
    def m(self, value: Any) -> None:
        m = _array(value, (self.n,), "m")
        if np.any(m <= 0):
            raise ValueError(f"masses must be > 0, got m[{int(np.flatnonzero(m <= 0)[0])}] = {m[m <= 0][0]}")
        self._m = m

    @property
    def x(self) -> np.ndarray:
        """Positions, (n, 3) (a copy: set the whole array to change them)."""
        return self._x.copy()

    @x.setter
    def x(self, value: Any) -> None:
        self._x = _array(value, (self.n, 3), "x")

    @property
    def v(self) -> np.ndarray:
        """Velocities, (n, 3) (a copy: set the whole array to change them)."""
        return self._v.copy()

    @v.setter
    def v(self, value: Any) -> None:
        self._v = _array(value, (self.n, 3), "v")

    @property
    def state(self) -> np.ndarray:
        """The state as the scene's CSV has it: positions, then momenta ``m v`` (n-body)
        or velocities (charged particles), flat; settable."""
        rate = self._v * self._m[:, None] if self.model == "n-body" else self._v
        return np.concatenate([self._x.ravel(), rate.ravel()])

    @state.setter
    def state(self, value: Any) -> None:
        y = _array(value, (6 * self.n,), "state")
        x, rate = y[: 3 * self.n].reshape(self.n, 3), y[3 * self.n :].reshape(self.n, 3)
        self._x = x
        self._v = rate / self._m[:, None] if self.model == "n-body" else rate

    def add(
        self,
        m: float = 1.0,
        x: Optional[Sequence[float]] = None,
        v: Optional[Sequence[float]] = None,
        *,
        name: Optional[str] = None,
        charge: Optional[float] = None,
        **elements: float,
    ) -> None:
        """Add a body: its mass ``m`` and either its position ``x`` and velocity ``v`` (3
        numbers each, default 0), or its orbital elements ``a, e, inc, Omega, omega`` and
        ``M`` or ``f`` (radians) about the centre of mass of the bodies before it (Jacobi,
        REBOUND's default) or the first body (``elements="heliocentric"``). Charged
        particles take ``charge`` (default 1) and ``x``, ``v``.
        """
        unknown = sorted(set(elements) - set(_ELEMENTS))
        if unknown:
            raise TypeError(f"unknown argument {unknown[0]!r}: a body takes m, x, v, name, or {', '.join(_ELEMENTS)}")
        name = name or f"body{self.n}"
        if name in self._names:
            raise ValueError(f"a body named {name!r} is already in the simulation")
        if elements and (x is not None or v is not None):
            raise ValueError("give a body's position and velocity (x, v) or its orbital elements, not both")
        if self.model == "charged-particles" and elements:
            raise ValueError("charged particles take a position and a velocity (x, v), not orbital elements")
        if self.model == "n-body" and charge is not None:
            raise TypeError("charge is for charged particles (Simulation('charged-particles', ...))")
        pos = _array([0.0] * 3 if x is None else x, (3,), "x")
        vel = _array([0.0] * 3 if v is None else v, (3,), "v")
        mass = _array([m], (1,), "m")[0]
        if mass <= 0:
            raise ValueError(f"a mass must be > 0, got m = {mass}")
        orbit = None
        if elements:
            if "a" not in elements or "e" not in elements:
                raise ValueError("orbital elements need at least a and e")
            orbit = {("i" if k == "inc" else k): float(val) for k, val in elements.items()}
        names = self._names + [name]
        masses = np.append(self._m, mass)
        charges = np.append(self._q, 1.0 if charge is None else float(charge))
        xs = np.vstack([self._x, pos])
        vs = np.vstack([self._v, vel])
        text = self._scene(names, masses, charges, xs, vs, orbit)
        y = np.asarray(_stormer.scene_info(scene_text=text, name="Simulation")["state"])
        n = len(names)
        self._names, self._m, self._q = names, masses, charges
        self._x = y[: 3 * n].reshape(n, 3)
        rate = y[3 * n :].reshape(n, 3)
        self._v = rate / masses[:, None] if self.model == "n-body" else rate

    def _scene(self, names, masses, charges, xs, vs, orbit=None) -> str:
        """The scene file of the bodies: what the Rust side reads and checks."""
        lines = [f'model = "{self.model}"', "[parameters]"]
        if self.model == "n-body":
            lines.append(f"G = {_toml_value(self.G)}")
            lines.append(f"elements = {_toml_value(self.elements)}")
        else:
            lines += [f"{k} = {_toml_value(v)}" for k, v in self.parameters.items()]
        table = "bodies" if self.model == "n-body" else "particles"
        # plain floats (the arrays are checked finite): repr is exact and the fastest to write
        row = lambda values: "[" + ", ".join(map(repr, values)) + "]"  # noqa: E731
        masses, charges, xs, vs = (np.asarray(a, dtype=float).tolist() for a in (masses, charges, xs, vs))
        for k, name in enumerate(names):
            lines += [f"[[{table}]]", f"name = {_toml_value(name)}", f"mass = {masses[k]!r}"]
            if self.model == "charged-particles":
                lines.append(f"charge = {charges[k]!r}")
            if orbit is not None and k == len(names) - 1:
                lines.append("orbit = { " + ", ".join(f"{key} = {_toml_value(v)}" for key, v in orbit.items()) + " }")
            else:
                lines += [f"position = {row(xs[k])}", f"velocity = {row(vs[k])}"]
        dt = float(self.dt)
        lines += ["[run]", f"method = {_toml_value(self._method_name())}", f"dt = {_toml_value(dt)}",
                  f"t0 = {_toml_value(float(self.t))}", f"t_end = {_toml_value(float(self.t) + dt)}"]
        return "\n".join(lines) + "\n"

    def _method_name(self) -> str:
        return self.method.name if isinstance(self.method, Method) else str(self.method)

    def integrate(self, t: float) -> Dict[str, Any]:
        """Integrate to time ``t`` at fixed steps ``dt`` (the last one shortened to land on
        ``t``; a span shorter than ``dt`` is one step of the span), with ``method``, in the ``split`` and with the ``corrector`` set. The state
        then holds the bodies at ``t``; returns the run's summary."""
        if self.n == 0:
            raise ValueError("the simulation has no bodies: add some with sim.add(...)")
        for what, a in (("x", self._x), ("v", self._v)):
            bad = np.argwhere(~np.isfinite(a))
            if bad.size:
                k, c = bad[0]
                raise ValueError(f"{what}[{k}, {c}] = {a[k, c]} (body {self._names[k]!r}) is not finite")
        t = float(t)
        if t == self.t:
            return {"text": f"no step: the simulation is at t = {t} already", "method": self._method_name(),
                    "scene": "Simulation", "steps": 0, "rejected": 0, "evaluations": 0, "energy_drift": None,
                    "max_error": None, "stop": None, "t_end": t}
        text = self._scene(self._names, self._m, self._q, self._x, self._v)
        # a span shorter than the step is one step of the span (REBOUND's last step too)
        dt = min(float(self.dt), abs(t - self.t))
        result = _stormer.run(
            scene_text=text,
            name="Simulation",
            method=self.method,
            dt=dt,
            t_end=t,
            every=2**62,
            split=self.split,
            corrector=self.corrector,
        )
        failure = result.pop("failure")
        y = result["y"][-1]
        n = self.n
        self._x = y[: 3 * n].reshape(n, 3).copy()
        rate = y[3 * n :].reshape(n, 3)
        self._v = rate / self._m[:, None] if self.model == "n-body" else rate.copy()
        self.t = float(result["t"][-1])
        if failure is not None:
            raise RunError(failure, result)
        return result["summary"]

    def step_jacobian(self, method: MethodArg = None, dt: Optional[float] = None) -> np.ndarray:
        """The exact Jacobian of one step from the bodies' state now (unsplit; dual numbers):
        see :func:`stormer.step_jacobian`. Defaults: the simulation's method and step."""
        if self.model != "n-body":
            raise ValueError("step_jacobian() is for n-body simulations")
        text = self._scene(self._names, self._m, self._q, self._x, self._v)
        method = self.method if method is None else method
        return _stormer.step_jacobian(method, float(self.dt if dt is None else dt), scene_text=text, name="Simulation")

    def energy(self) -> float:
        """The total energy of the bodies now (n-body: kinetic minus the pairs' potential)."""
        if self.model != "n-body":
            raise ValueError("energy() is for n-body simulations; a charged run's energy is in its summary")
        kinetic = 0.5 * float(np.sum(self._m[:, None] * self._v**2))
        potential = 0.0
        for i in range(self.n):
            d = np.linalg.norm(self._x[i + 1 :] - self._x[i], axis=1)
            potential -= self.G * float(np.sum(self._m[i] * self._m[i + 1 :] / d))
        return kinetic + potential

    @classmethod
    def from_scene(cls, scene: str, **settings: Any) -> "Simulation":
        """The bodies of an n-body scene (``"outer-solar-system"`` or a file), with the
        scene's method and step unless ``settings`` say otherwise."""
        info = _stormer.scene_info(scene)
        if info["model"] != "n-body":
            raise ValueError(f"{scene} is a {info['model']} scene; from_scene reads n-body scenes")
        sim = cls(G=info["G"], method=settings.pop("method", info["method"]), dt=settings.pop("dt", info["dt"]),
                  split=settings.pop("split", info["split"]), **settings)
        n = len(info["masses"])
        y = np.asarray(info["state"])
        sim._names = list(info["names"])
        sim._m = np.asarray(info["masses"], dtype=float)
        sim._q = np.ones(n)
        sim._x = y[: 3 * n].reshape(n, 3).copy()
        sim._v = y[3 * n :].reshape(n, 3) / sim._m[:, None]
        sim.t = float(info["t0"])
        return sim


def _array(value: Any, shape: Tuple[int, ...], what: str) -> np.ndarray:
    """``value`` as a float64 array of ``shape``, finite, or the error naming what is wrong."""
    try:
        a = np.array(value, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{what} must be numbers (float64), got {type(value).__name__}: {e}") from None
    if a.shape != shape:
        raise ValueError(f"{what} must have shape {shape}, got {a.shape}")
    bad = np.argwhere(~np.isfinite(a))
    if bad.size:
        index = ", ".join(str(i) for i in bad[0])
        raise ValueError(f"{what}[{index}] = {a[tuple(bad[0])]} is not finite")
    return a
