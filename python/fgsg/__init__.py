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
import json
import os
import sys

# The JIT (lib/libfgsg_llvm.so) resolves fgsg's own functions from the process: the
# engine is loaded so that they are visible to it, and the plugins are looked up beside
# the build or installation this package belongs to unless FGSG_LIBDIR says otherwise.
_here = os.path.dirname(os.path.abspath(__file__))
# build/python/fgsg -> build/lib; PREFIX/lib/python3/dist-packages/fgsg -> PREFIX/lib.
for _candidate in (os.path.join(_here, "..", "..", "lib"), os.path.join(_here, "..", "..", "..")):
    if "FGSG_LIBDIR" not in os.environ and os.path.isfile(os.path.join(_candidate, "libfgsg_llvm.so")):
        os.environ["FGSG_LIBDIR"] = os.path.normpath(_candidate)
_flags = sys.getdlopenflags()
sys.setdlopenflags(_flags | os.RTLD_GLOBAL)
try:
    from . import _fgsg
finally:
    sys.setdlopenflags(_flags)

__all__ = ["Grammar", "Result", "GrammarError"]


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
    `assets` and `symbols` naming the indices; stats: the figures of `fgsg run --stats`."""

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

    def instance_params(self, i):
        """Instance i's parameters as the grammar typed them (numbers, booleans, strings, vectors)."""
        return json.loads(self._native.instance_params_json(i))

    def write(self, path):
        """Writes the mesh (.glb, .obj or .ply by the extension), atomically."""
        self._native.write(os.fspath(path))


class Grammar:
    """A compiled grammar. Build it with from_file or from_text; generate() derives it."""

    def __init__(self, native):
        self._native = native

    @classmethod
    def from_file(cls, path):
        """Compiles the grammar in `path` (its assets are looked up beside it, as fgsg run does)."""
        return cls(_raising(_fgsg.Grammar.from_file, os.fspath(path)))

    @classmethod
    def from_library(cls, path, name=""):
        """Loads a grammar library built by `fgsg compile FILE -o libNAME.so`: its compiled
        code runs (no JIT); `name` is NAME when the file is named otherwise."""
        return cls(_raising(_fgsg.Grammar.from_library, os.fspath(path), name))

    @classmethod
    def from_text(cls, text, name="<text>.fgsg"):
        """Compiles grammar `text`; `name` names it in errors (and its folder holds its assets)."""
        return cls(_raising(_fgsg.Grammar.compile, text, name))

    @property
    def attrs(self):
        """The names of the grammar's attributes (settable in generate)."""
        return list(self._native.attrs)

    def generate(self, seed=1, attrs=None, surface=None, max_shapes=None, engine="jit", lots=None):
        """Derives the grammar: `seed`, attribute values by name (numbers, booleans,
        strings), a surface mesh file replacing the grammar's, a shape limit, the engine
        ("jit", or "interp": the reference interpreter; the results are equal), and lots:
        a GeoJSON or OBJ/PLY/OFF file of footprints, derived once per lot (fgsg run --lots)."""
        return Result(_raising(self._native.generate, int(seed), dict(attrs or {}),
                               None if surface is None else os.fspath(surface), max_shapes, engine,
                               None if lots is None else os.fspath(lots)))
