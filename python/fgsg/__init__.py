"""fgsg: field-guided shape grammars from Python.

    import fgsg
    g = fgsg.Grammar.from_file("examples/mueller_building.fgsg")
    r = g.generate(seed=7, attrs={"lot_width": 24})
    r.positions, r.indices, r.normals   # numpy views of the mesh, no copies
    r.instances                         # structured array: asset, symbol, transform, color, params
    r.write("building.glb")             # the bytes `fgsg run --seed 7 --set lot_width=24` writes

Grammars that do not compile, and derivations that fail, raise GrammarError with the
file, line, column, code and message of the first error. generate() releases the GIL:
threads derive in parallel.
"""
import base64
import html
import json
import math
import numbers
import os
import sys
import warnings
from typing import NamedTuple

# The JIT (lib/libfgsg_llvm.so) resolves fgsg's own functions from the process: the
# engine is loaded so that they are visible to it, and the plugins are looked up beside
# the build or installation this package belongs to unless FGSG_LIBDIR says otherwise.
_here = os.path.dirname(os.path.abspath(__file__))
# build/python/fgsg -> build/lib; PREFIX/lib/python3/dist-packages/fgsg -> PREFIX/lib;
# a pip-installed wheel (setup.py) -> fgsg/lib.
for _candidate in (os.path.join(_here, "..", "..", "lib"), os.path.join(_here, "..", "..", ".."),
                   os.path.join(_here, "lib")):
    if "FGSG_LIBDIR" not in os.environ and os.path.isfile(os.path.join(_candidate, "libfgsg_llvm.so")):
        os.environ["FGSG_LIBDIR"] = os.path.normpath(_candidate)
_flags = sys.getdlopenflags()
sys.setdlopenflags(_flags | os.RTLD_GLOBAL)
try:
    from . import _fgsg
finally:
    sys.setdlopenflags(_flags)

__all__ = ["Grammar", "Result", "GrammarError", "Attr", "Annotation", "SceneNode", "__version__"]
__version__ = _fgsg.__version__  # the project's version (CMakeLists.txt)


class GrammarError(Exception):
    """A grammar's error: `file`, `line`, `column`, `code` ("E002", "R010" ...) and
    `message` of the first one; `diagnostics` lists them all (dicts with the same keys and
    `text`, the compiler's formatted line with its caret)."""

    def __init__(self, diagnostics):
        self.diagnostics = list(diagnostics)
        first = self.diagnostics[0] if self.diagnostics else {}
        self.file = first.get("file", "")
        self.line = first.get("line", 0)
        self.column = first.get("column", 0)
        self.code = first.get("code", "")
        self.message = first.get("message", "")
        super().__init__("\n".join(d.get("text", d.get("message", "")) for d in self.diagnostics))


def _raising(call, *args, **kwargs):
    try:
        return call(*args, **kwargs)
    except _fgsg.CompileError as e:
        raise GrammarError(e.args[0]) from None


class Result:
    """A derived model. positions, normals, colors: (n, 3) float32; indices: (m, 3)
    uint32 (numpy views that keep the result alive); instances: a structured array
    (asset, symbol, transform 4x4 float64, color, param_offset, param_count) with
    `assets` and `symbols` naming the indices; stats: the figures of `fgsg run --stats`;
    reports: what Report(key, value) collected, as `fgsg run --report` writes it (a dict:
    "starts", one per start shape, each with its "reports" by key, and "all"); prints: the
    (line, column, text) of each Print, in the order they ran."""

    def __init__(self, native):
        self._native = native

    positions = property(lambda self: self._native.positions)
    normals = property(lambda self: self._native.normals)
    colors = property(lambda self: self._native.colors)
    indices = property(lambda self: self._native.indices)
    instances = property(lambda self: self._native.instances)
    assets = property(lambda self: self._native.assets)
    symbols = property(lambda self: self._native.symbols)
    stats = property(lambda self: self._native.stats)
    prints = property(lambda self: self._native.prints)

    @property
    def reports(self):
        return json.loads(self._native.reports_json())

    def instance_params(self, i):
        """Instance i's parameters as the grammar typed them (numbers, booleans, strings, vectors)."""
        return json.loads(self._native.instance_params_json(i))

    def scene(self, instancing="auto", group_by="symbol"):
        """The nodes of the glTF scene `fgsg run -o x.glb --instancing I --group-by G` writes,
        as a list of SceneNode, a node before its children: per start shape (lot, seed,
        axiom) a node named after it whose extras hold its "properties", "attrs" and
        "reports"; under it a node per group; under those a node per instanced mesh (or per
        instance with instancing="nodes", and per mirrored instance). instancing: "auto",
        "on", "nodes" or "off"; group_by: "symbol" or "none" (rule and label groups need the
        rule of each instance, which only fgsg run records)."""
        if instancing not in ("auto", "on", "nodes", "off"):
            raise ValueError(f"instancing must be 'auto', 'on', 'nodes' or 'off', got {instancing!r}")
        if group_by not in ("symbol", "none"):
            raise ValueError(f"group_by must be 'symbol' or 'none', got {group_by!r}")
        nodes = json.loads(self._native.scene_nodes_json(instancing, group_by))
        # The transform column-major in the JSON, as rows here (as `instances` gives them).
        return [SceneNode(n["name"], n["parent"], tuple(tuple(n["transform"][4 * c + r] for c in range(4)) for r in range(4)),
                          n["extras"], n["meshes"], n["instances"]) for n in nodes]

    def write(self, path):
        """Writes the mesh (.glb, .obj or .ply by the extension), atomically."""
        self._native.write(os.fspath(path))

    def preview_png(self, width=800, height=600):
        """The picture `fgsg run --preview` draws of the mesh, as PNG bytes."""
        return self._native.preview_png(_whole("width", width, 8192), _whole("height", height, 8192))

    def _repr_html_(self):
        """Jupyter's view: the preview inline (a base64 PNG) when there is a mesh to draw,
        else a table of the stats."""
        stats = self.stats
        if stats.get("triangles", 0) or stats.get("lines", 0):
            data = base64.b64encode(self.preview_png(480, 360)).decode("ascii")
            return (f'<img src="data:image/png;base64,{data}" width="480" height="360" '
                    f'alt="{html.escape(repr(self))}"/>')
        rows = "".join(f"<tr><td>{html.escape(name)}</td><td>{value}</td></tr>" for name, value in stats.items())
        return f"<table><caption>{html.escape(repr(self))}</caption>{rows}</table>"

    def __repr__(self):
        stats = self.stats
        return (f"<fgsg.Result: {stats.get('triangles', 0)} triangles, {stats.get('instances', 0)} instances, "
                f"{stats.get('shapes', 0)} shapes>")


class SceneNode(NamedTuple):
    """A node of Result.scene(): its `name`, `parent` (the index of its parent in the list,
    -1 for a start shape's node), `transform` (4x4 rows, relative to the parent; the
    identity but for a node per instance), `extras` (the glTF node's extras, a dict),
    `meshes` (what it draws itself: baked parts, or its one shared mesh) and `instances`
    (the instances it and its descendants draw)."""
    name: str
    parent: int
    transform: tuple
    extras: dict
    meshes: int
    instances: int


class _AttrFields(NamedTuple):
    name: str
    kind: str
    default: object


def _number(text):
    try:
        return float(text)
    except ValueError:
        return None


class Attr(_AttrFields):
    """A grammar's attribute: its `name`, `kind` ("num", "bool", "str" or "vec3") and
    `default` (a float, bool, str or a tuple of 3 floats) — the tuple (name, kind, default)
    it always was, so equality and unpacking are unchanged — and its `annotations` (a
    .cga file's @Range, @Enum ... as Annotation; [] for every .fgsg attribute, which has
    none), with what they say: `range` (min, max) floats from @Range(min=, max=) or
    @Range(lo, hi), `step` from @Range's stepsize, `enum` the tuple of @Enum's values
    (floats for a num attribute, else text); None where not annotated."""

    annotations = ()  # _make and _replace build an Attr without them

    def __new__(cls, name, kind, default, annotations=()):
        self = super().__new__(cls, name, kind, default)
        self.annotations = list(annotations)
        return self

    def _first(self, name):
        return next((a for a in self.annotations if a.name == name), None)

    @property
    def range(self):
        note = self._first("Range")
        if note is None:
            return None
        low, high = note.named.get("min"), note.named.get("max")
        if low is None and high is None and len(note.args) >= 2:
            low, high = note.args[0], note.args[1]
        low, high = _number(low) if low is not None else None, _number(high) if high is not None else None
        return None if low is None or high is None else (low, high)

    @property
    def step(self):
        note = self._first("Range")
        step = note.named.get("stepsize") if note is not None else None
        return None if step is None else _number(step)

    @property
    def enum(self):
        note = self._first("Enum")
        if note is None:
            return None
        if self.kind == "num":
            values = tuple(_number(v) for v in note.args)
            return None if None in values else values
        return tuple(note.args)

    def __repr__(self):
        extra = "".join(f", {key}={value!r}" for key, value in
                        (("range", self.range), ("step", self.step), ("enum", self.enum)) if value is not None)
        return f"Attr(name={self.name!r}, kind={self.kind!r}, default={self.default!r}{extra})"


class Annotation(NamedTuple):
    """An attribute's annotation in a .cga grammar (metadata for inspectors, no effect on
    deriving): `name` without its @ ("Range", "Enum", "Hidden", "Group", "Order",
    "Description" ...), `args` its positional arguments and `named` its keyed ones
    (`@Range(min=0, max=10)`), each as text: a string without its quotes, anything else as
    written ("0", "10", "2.5")."""
    name: str
    args: tuple
    named: dict


_SEED_MAX = 2**64 - 1
_STEP_MAX = 2**31 - 1  # fgsg run --step's range


def _start_rule(value):
    """from_file's and from_text's start_rule as the engine takes it: "" for None."""
    if value is None:
        return ""
    if not isinstance(value, str) or not value:
        raise TypeError(f"start_rule must be a rule name (a non-empty str) or None, not {value!r}")
    return value


def _whole(what, value, high=_SEED_MAX):
    """`value` as an int from 0 to `high`: a TypeError for a non-integer (7.9, "7", True),
    a ValueError for one out of range."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{what} must be an int, not {type(value).__name__}")
    value = int(value)
    if not 0 <= value <= high:
        raise ValueError(f"{what} must be from 0 to {high}, got {value}")
    return value


def _positive_seconds(value):
    """max_seconds as a float: a TypeError for a non-number, a ValueError unless positive and finite."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"max_seconds must be a number (int or float), not {type(value).__name__}")
    try:
        seconds = float(value)
    except OverflowError:  # an int beyond float's range
        seconds = math.inf
    if not (math.isfinite(seconds) and seconds > 0):
        raise ValueError(f"max_seconds must be a positive, finite number of seconds, got {value!r}")
    return seconds


def _attr_text(key, value, attr):
    """The value of `attrs[key]` as the engine reads it, after checking its Python type
    against the attribute's kind (a TypeError or ValueError naming `attrs[key]`)."""
    where = f"attrs[{key!r}]"
    if attr is None:  # not declared: the engine says so (a GrammarError listing those that are)
        return "true" if value is True else "false" if value is False else str(value)

    def number(v, what):
        if isinstance(v, bool) or not isinstance(v, numbers.Real):
            raise TypeError(f"{where} must be {what}, not {type(v).__name__}")
        try:
            v = float(v)
        except OverflowError:
            v = math.inf
        if not math.isfinite(v):
            raise ValueError(f"{where} must be a finite number, got {v}")
        return repr(v)

    if attr.kind == "bool":
        if type(value).__name__ not in ("bool", "bool_"):  # numpy's bool_ too
            raise TypeError(f"{where} must be a bool, not {type(value).__name__}")
        return "true" if value else "false"
    if attr.kind == "str":
        if not isinstance(value, str):
            raise TypeError(f"{where} must be a str, not {type(value).__name__}")
        return value
    if attr.kind == "vec3":
        if isinstance(value, (str, bytes)) or not hasattr(value, "__len__"):
            raise TypeError(f"{where} must be 3 numbers (a tuple, list or array), not {type(value).__name__}")
        if len(value) != 3:
            raise ValueError(f"{where} must be 3 numbers, got {len(value)}")
        return ",".join(number(v, "3 numbers") for v in value)
    return number(value, "a number (int or float)")


class Grammar:
    """A compiled grammar. Build it with from_file or from_text; generate() derives it."""

    def __init__(self, native):
        self._native = native

    @classmethod
    def from_file(cls, path, start_rule=None):
        """Compiles the grammar in `path` (its assets are looked up beside it, as fgsg run does).
        `start_rule`: a .cga grammar's rule for its lots instead of its @StartRule (as
        fgsg run --start-rule); a rule the file lacks, or an fgsg grammar, is a GrammarError."""
        return cls(_raising(_fgsg.Grammar.from_file, os.fspath(path), _start_rule(start_rule)))

    @classmethod
    def from_library(cls, path, name=""):
        """Loads a grammar library built by `fgsg compile FILE -o libNAME.so`: its compiled
        code runs (no JIT); `name` is NAME when the file is named otherwise."""
        return cls(_raising(_fgsg.Grammar.from_library, os.fspath(path), name))

    @classmethod
    def from_text(cls, text, name="<text>.fgsg", start_rule=None):
        """Compiles grammar `text`; `name` names it in errors (and its folder holds its assets);
        `start_rule` as in from_file (a name ending .cga makes the text CGA)."""
        return cls(_raising(_fgsg.Grammar.compile, text, name, _start_rule(start_rule)))

    @property
    def name(self):
        """The grammar's file (or the name given to from_text)."""
        return self._native.name

    @property
    def attrs(self):
        """The grammar's attributes (settable in generate), in declaration order: a dict
        of name -> Attr(name, kind, default) with its annotations and their range, step
        and enum (iterating gives the names, as it always did)."""
        notes = self.attr_annotations
        return {name: Attr(name, kind, default, notes.get(name, ())) for name, kind, default in self._native.attrs}

    @property
    def attr_annotations(self):
        """Each attribute's annotations (a .cga file's @Range, @Enum, @Hidden, @Group,
        @Order, @Description ...), in declaration order: a dict of name -> list of
        Annotation(name, args, named) in the order written; [] for an attribute without
        any (every .fgsg attribute)."""
        return {name: [Annotation(n, tuple(args), dict(named)) for n, args, named in notes]
                for name, notes in self._native.attr_annotations}

    @property
    def source(self):
        """The grammar's text followed by each imported module's, as bytes (what a
        compiled library embeds; fgsg.batch hashes it)."""
        return self._native.source

    def __repr__(self):
        kind = "library" if self._native.is_library else "grammar"
        return f"<fgsg.Grammar {self.name!r} ({kind}, {len(self._native.attrs)} attrs)>"

    def generate(self, seed=1, attrs=None, surface=None, max_shapes=None, engine="jit", lots=None,
                 max_depth=None, max_seconds=None, step=None):
        """Derives the grammar: `seed` (an int from 0 to 2**64 - 1), attribute values by
        name (a number for a num attribute, a bool, a str, 3 numbers for a vec3), a surface
        mesh file replacing the grammar's, a shape limit, the engine ("jit", or "interp":
        the reference interpreter; the results are equal), and lots: a GeoJSON or
        OBJ/PLY/OFF file of footprints, derived once per lot (fgsg run --lots). The limits
        are fgsg run's --max-shapes, --max-depth and --max-seconds (None: their defaults);
        a derivation that meets one keeps what it derived. `step` (fgsg run --step): an
        L-system (`derive parallel N;`) derived that many steps (an int from 0, its axiom,
        to 2**31 - 1) instead of its length; past the length, the length with a
        UserWarning; None: the whole length.

        A value of the wrong type is a TypeError, a seed, limit or step out of range a
        ValueError (so is a step for a grammar that is no L-system); an attribute the
        grammar does not declare is a GrammarError (R010)."""
        seed = _whole("seed", seed)
        if step is not None:
            step = _whole("step", step, _STEP_MAX)
        if max_shapes is not None:
            max_shapes = _whole("max_shapes", max_shapes)
        if max_depth is not None:
            max_depth = _whole("max_depth", max_depth, 2**32 - 1)
        if max_seconds is not None:
            max_seconds = _positive_seconds(max_seconds)
        if attrs is None:
            attrs = {}
        if not hasattr(attrs, "items"):
            raise TypeError(f"attrs must be a dict of attribute names to values, not {type(attrs).__name__}")
        declared = self.attrs
        texts = []
        for key, value in attrs.items():
            if not isinstance(key, str):
                raise TypeError(f"attrs keys must be str (attribute names), not {type(key).__name__}")
            texts.append((key, _attr_text(key, value, declared.get(key))))
        if not isinstance(engine, str):
            raise TypeError(f"engine must be a str ('jit' or 'interp'), not {type(engine).__name__}")
        if step is not None:
            self._check_step(step, texts)
        return Result(_raising(self._native.generate, seed, texts,
                               None if surface is None else os.fspath(surface), max_shapes, engine,
                               None if lots is None else os.fspath(lots), max_depth, max_seconds, step))

    def _check_step(self, step, texts):
        """step= against the derivation's length with these attribute values (as fgsg run
        --step): a ValueError for a grammar that is no L-system, a UserWarning past the
        length (the length is derived: lpfg's animate mode stops there too)."""
        length = _raising(self._native.derivation_length, texts)
        if length < 0:
            raise ValueError(f"step={step}: {self.name} is no L-system: its derivation is sequential "
                             "(derive breadthfirst or depthfirst), which has no steps; step counts the "
                             "steps of `derive parallel N;`")
        if step > length:
            warnings.warn(f"step={step} is past {self.name}'s derivation length {length}: step {length}, "
                          "its last, is derived (as lpfg's animate mode stops there)", UserWarning, stacklevel=3)
