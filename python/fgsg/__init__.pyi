# Type stubs of the fgsg package (python/fgsg/__init__.py).
import os
from typing import Any, Mapping, NamedTuple, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str

class Attr(NamedTuple):  # a tuple of these three, with more as attributes
    name: str
    kind: str  # "num", "bool", "str" or "vec3"
    default: Union[float, bool, str, tuple[float, float, float]]
    def __new__(cls, name: str, kind: str, default: Any, annotations: Sequence["Annotation"] = ...) -> "Attr": ...
    @property
    def annotations(self) -> list["Annotation"]: ...
    @property
    def range(self) -> Optional[tuple[float, float]]: ...  # @Range(min=, max=)
    @property
    def step(self) -> Optional[float]: ...  # @Range(stepsize=)
    @property
    def enum(self) -> Optional[tuple[Union[float, str], ...]]: ...  # @Enum(...)

class Annotation(NamedTuple):
    name: str  # "Range", "Enum", "Hidden", "Group", "Order", "Description" ...
    args: tuple[str, ...]  # positional arguments as text
    named: dict[str, str]  # keyed arguments as text

class SceneNode(NamedTuple):
    name: str
    parent: int  # index in the list; -1 for a start shape's node
    transform: tuple[tuple[float, float, float, float], ...]  # 4x4 rows, relative to the parent
    extras: dict[str, Any]
    meshes: int
    instances: int

class GrammarError(Exception):
    diagnostics: list[dict[str, Any]]
    file: str
    line: int
    column: int
    code: str
    message: str
    def __init__(self, diagnostics: list[dict[str, Any]]) -> None: ...

class Result:
    @property
    def positions(self) -> npt.NDArray[np.float32]: ...
    @property
    def normals(self) -> npt.NDArray[np.float32]: ...
    @property
    def colors(self) -> npt.NDArray[np.float32]: ...
    @property
    def indices(self) -> npt.NDArray[np.uint32]: ...
    @property
    def instances(self) -> npt.NDArray[np.void]: ...
    @property
    def assets(self) -> list[str]: ...
    @property
    def symbols(self) -> list[str]: ...
    @property
    def stats(self) -> dict[str, int]: ...
    @property
    def reports(self) -> dict[str, Any]: ...
    @property
    def prints(self) -> list[tuple[int, int, str]]: ...
    def instance_params(self, i: int) -> list[Any]: ...
    def scene(self, instancing: str = ..., group_by: str = ...) -> list["SceneNode"]: ...
    def write(self, path: Union[str, os.PathLike[str]]) -> None: ...
    def preview_png(self, width: int = ..., height: int = ...) -> bytes: ...
    def _repr_html_(self) -> str: ...

class Grammar:
    @classmethod
    def from_file(cls, path: Union[str, os.PathLike[str]], start_rule: Optional[str] = ...) -> "Grammar": ...
    @classmethod
    def from_library(cls, path: Union[str, os.PathLike[str]], name: str = ...) -> "Grammar": ...
    @classmethod
    def from_text(cls, text: str, name: str = ..., start_rule: Optional[str] = ...) -> "Grammar": ...
    @property
    def name(self) -> str: ...
    @property
    def attrs(self) -> dict[str, Attr]: ...
    @property
    def attr_annotations(self) -> dict[str, list[Annotation]]: ...
    @property
    def source(self) -> bytes: ...
    def generate(self, seed: int = ...,
                 attrs: Optional[Mapping[str, Union[int, float, bool, str, Sequence[float]]]] = ...,
                 surface: Optional[Union[str, os.PathLike[str]]] = ..., max_shapes: Optional[int] = ...,
                 engine: str = ..., lots: Optional[Union[str, os.PathLike[str]]] = ...,
                 max_depth: Optional[int] = ..., max_seconds: Optional[float] = ...,
                 step: Optional[int] = ...) -> Result: ...
