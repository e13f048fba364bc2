# Type stub of the frictionviz package (docs/python.md). Angles are in DEGREES (theta_deg) everywhere.
from os import PathLike
from typing import Any, Dict, List, Literal, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

ArrayLike = npt.ArrayLike
FloatArray = Union[np.float64, npt.NDArray[np.float64]]
Path = Union[str, PathLike[str]]

DEFAULT_TOLERANCE: float

class NumericalFailure(ArithmeticError):
    result: Any
    failed: List[Tuple[int, ...]]
    def __init__(self, message: str, result: Any = ..., failed: Optional[List[tuple]] = ...) -> None: ...

class RatioResult:
    r_x: FloatArray
    r_y: FloatArray
    error_estimate: FloatArray
    periods: Union[np.int64, npt.NDArray[np.int64]]
    status: Union[np.str_, npt.NDArray[np.str_]]
    ok: Union[np.bool_, npt.NDArray[np.bool_]]
    shape: Tuple[int, ...]
    @property
    def failed(self) -> List[Tuple[int, ...]]: ...

def ratio(
    zeta: ArrayLike,
    theta_deg: ArrayLike,
    rdisp: Optional[ArrayLike] = ...,
    i: Optional[ArrayLike] = ...,
    model: Literal["dahl", "rigid"] = ...,
    tolerance: float = ...,
    threads: int = ...,
    start: Literal["rest", "sliding"] = ...,
    raise_on_failure: bool = ...,
) -> RatioResult: ...
def rigid_ratio(zeta: ArrayLike, theta_deg: ArrayLike) -> Tuple[FloatArray, FloatArray]: ...

class Trace:
    tau: npt.NDArray[np.float64]
    Px: npt.NDArray[np.float64]
    Py: npt.NDArray[np.float64]
    Tx: npt.NDArray[np.float64]
    Ty: npt.NDArray[np.float64]
    z: npt.NDArray[np.float64]
    Fx: npt.NDArray[np.float64]
    Fy: npt.NDArray[np.float64]
    stick: npt.NDArray[np.bool_]
    r_x: float
    r_y: float
    error_estimate: float
    periods: int
    status: str
    @property
    def ok(self) -> bool: ...

def trace(
    zeta: float,
    theta_deg: float,
    rdisp: float,
    i: float,
    tolerance: float = ...,
    start: Literal["rest", "sliding"] = ...,
    raise_on_failure: bool = ...,
) -> Trace: ...

class Measurements:
    file: str
    zeta: npt.NDArray[np.float64]
    r_x: npt.NDArray[np.float64]
    theta_deg: Optional[npt.NDArray[np.float64]]
    sigma: Optional[npt.NDArray[np.float64]]
    vb: Optional[npt.NDArray[np.float64]]
    label: List[str]
    line: npt.NDArray[np.int64]
    synthetic: bool
    def __len__(self) -> int: ...

def read_measurements(
    path: Path, amplitude_um: Optional[float] = ..., frequency_khz: Optional[float] = ...
) -> Measurements: ...

class FitResult:
    best: dict
    candidates: List[dict]
    status: str
    detail: str
    file: str
    @property
    def rdisp(self) -> float: ...
    @property
    def i(self) -> float: ...
    @property
    def ok(self) -> bool: ...

def fit(
    data: Union[Path, Measurements],
    theta_deg: Optional[float] = ...,
    i: Union[Literal[0, 1, "0", "1", "auto"]] = ...,
    amplitude_um: Optional[float] = ...,
    frequency_khz: Optional[float] = ...,
    threads: int = ...,
    raise_on_failure: bool = ...,
) -> FitResult: ...

class Figure:
    id: str
    format: str
    data: bytes
    title: str
    caption: str
    parameters: Dict[str, Any]
    def __init__(self, id: str, data: bytes, format: str, title: str = ..., caption: str = ...,
                 parameters: Optional[Dict[str, Any]] = ...,
                 csv: Optional[List[Tuple[str, str]]] = ...) -> None: ...
    @property
    def tables(self) -> Dict[str, np.ndarray]:
        """Table name ("map", "map-best-angle": the CSV file's name without .csv) -> structured array with
        the CSV's columns (numbers float64, empty cells NaN; text columns str)."""
    def csv(self, name: Optional[str] = ...) -> str:
        """The CSV text `frictionviz render` writes for table `name` (default: the one named by the id)."""
    def save_spec(self, path: Path) -> None: ...
    def _repr_png_(self) -> Optional[bytes]: ...
    def _repr_svg_(self) -> Optional[str]: ...
    def save(self, path: Path, data: bool = ...) -> None: ...

def figures() -> List[Tuple[str, str, List[str]]]: ...
def render(
    id: str,
    out: Optional[Path] = ...,
    format: Literal["png", "svg", "pdf"] = ...,
    size: Tuple[int, int] = ...,
    scale: float = ...,
    **params: Any,
) -> Union[Figure, Path]: ...
