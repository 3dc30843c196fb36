"""Type stubs of the native module ``stormer._stormer`` (Rust, pyo3). The public API is
``stormer`` (``stormer/__init__.py``, annotated); these are the calls it makes."""

from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

class Method:
    """A method of the catalog, a method file, or a method given as data."""

    @staticmethod
    def named(name: str) -> "Method": ...
    @staticmethod
    def from_toml(text: str, origin: str = "Python") -> "Method": ...
    @property
    def name(self) -> str: ...
    def info(self) -> Dict[str, Any]: ...
    def verify_json(self) -> Tuple[str, List[str]]: ...

def methods_json() -> str: ...
def verify_json(name: str) -> Tuple[str, List[str]]: ...
def run(
    scene: Optional[str] = None,
    scene_text: Optional[str] = None,
    name: str = "scene",
    method: Union[str, Method, None] = None,
    dt: Optional[float] = None,
    t_end: Optional[float] = None,
    every: Optional[int] = None,
    save_at: Optional[Sequence[float]] = None,
    split: Optional[str] = None,
    corrector: Optional[int] = None,
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    compensated: bool = False,
    max_steps: Optional[int] = None,
    numbers: Optional[Mapping[str, float]] = None,
) -> Dict[str, Any]: ...
def scene_info(scene: Optional[str] = None, scene_text: Optional[str] = None, name: str = "scene") -> Dict[str, Any]: ...
def step_jacobian(
    method: Union[str, Method],
    dt: float,
    scene: Optional[str] = None,
    scene_text: Optional[str] = None,
    name: str = "scene",
) -> npt.NDArray[np.float64]: ...
def ensemble(
    scene: str,
    vary: Sequence[Tuple[str, float, float, int]],
    method: Optional[str] = None,
    dt: Optional[float] = None,
    t_end: Optional[float] = None,
    jobs: Optional[int] = None,
) -> Dict[str, Any]: ...
def integrate(
    f: Callable[[float, npt.NDArray[np.float64]], Any],
    y0: Sequence[float],
    t_end: float,
    method: Union[str, Method, None] = None,
    dt: Optional[float] = None,
    t0: float = 0.0,
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    every: int = 1,
    save_at: Optional[Sequence[float]] = None,
    max_steps: Optional[int] = None,
) -> Dict[str, Any]: ...
