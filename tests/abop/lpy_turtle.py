"""An independent 3D turtle written from L-Py's (PlantGL's) documented conventions, to
check fgsg's turtle vertex by vertex. Written here from the conventions alone:

* the frame is heading H, left L, up U with H x L = U; L-Py starts it at H = (0, 0, 1),
  L = (0, -1, 0), U = (1, 0, 0) in its world, whose up is +Z;
* every turn is a right-handed rotation (Rodrigues' matrix) of the frame about one of its
  own axes: `+` about U by +a (H turns towards L), `-` by -a; `&` ("pitch down") about L
  by +a (H turns towards -U), `^` by -a; `/` (L-Py's RollL, lpfg's "roll right") about H
  by +a (L turns towards U), `\\` by -a; `|` about U by 180 degrees;
* `$` (RollToVert) makes L = V x H / |V x H| with V the world's up, then U = H x L;
* tropism (ABOP eq. 2.4): after each F, H turns about H x T by e |H x T| radians, and L
  and U with it.

fgsg's world has +Y up and starts the turtle at H = +Y, L = -X, U = +Z (lpfg's frame). The
map from L-Py's world to fgsg's, (x, y, z) -> (y, z, x), carries L-Py's start frame onto
fgsg's and is a rotation (a cyclic permutation of the axes, no mirror): a plant drawn
by this turtle, mapped so, is the plant L-Py draws, seen in fgsg's axes."""
import math


def to_fgsg(v):
    """A point or vector of L-Py's world in fgsg's axes."""
    return (v[1], v[2], v[0])


def from_fgsg(v):
    """A vector given in fgsg's axes (a tropism vector) in L-Py's world."""
    return (v[2], v[0], v[1])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(sum(c * c for c in a))


def rotation(axis, degrees=None, radians=None):
    """The right-handed rotation matrix (rows) about `axis` (normalised here: a frame
    turned thousands of times about its own, slightly denormalised, axes would otherwise
    grow without bound)."""
    t = math.radians(degrees) if radians is None else radians
    c, s = math.cos(t), math.sin(t)
    x, y, z = (a / norm(axis) for a in axis)
    k = 1 - c
    return ((k * x * x + c, k * x * y - s * z, k * x * z + s * y),
            (k * x * y + s * z, k * y * y + c, k * y * z - s * x),
            (k * x * z - s * y, k * y * z + s * x, k * z * z + c))


def apply(m, v):
    return tuple(sum(m[r][k] * v[k] for k in range(3)) for r in range(3))


class Turtle:
    """L-Py's turtle state: position P and frame H, L, U, in L-Py's world."""

    def __init__(self):
        self.P, self.H, self.L, self.U = (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, -1.0, 0.0), (1.0, 0.0, 0.0)
        self.width = 0.0
        self.tropism, self.elasticity = (0.0, 0.0, 1.0), 0.0

    def state(self):
        return (self.P, self.H, self.L, self.U, self.width, self.tropism, self.elasticity)

    def restore(self, s):
        self.P, self.H, self.L, self.U, self.width, self.tropism, self.elasticity = s

    def _rotate(self, m):
        self.H, self.L, self.U = apply(m, self.H), apply(m, self.L), apply(m, self.U)

    def turn(self, symbol, a):
        if symbol in "+-":
            self._rotate(rotation(self.U, a if symbol == "+" else -a))
        elif symbol in "&^":
            self._rotate(rotation(self.L, a if symbol == "&" else -a))
        elif symbol in "/\\":
            self._rotate(rotation(self.H, a if symbol == "/" else -a))
        elif symbol == "|":
            self._rotate(rotation(self.U, 180.0))
        elif symbol == "$":
            left = cross((0.0, 0.0, 1.0), self.H)
            n = norm(left)
            if n > 1e-12:
                self.L = tuple(c / n for c in left)
                self.U = cross(self.H, self.L)
        else:
            raise ValueError(symbol)

    def forward(self, length):
        """Moves `length` along H; returns the segment (start, end) in L-Py's world."""
        start = self.P
        self.P = tuple(p + length * h for p, h in zip(self.P, self.H))
        return start, self.P

    def bend(self, elasticity=None):
        """ABOP eq. 2.4 after a segment: H turns about H x T by e |H x T|."""
        e = self.elasticity if elasticity is None else elasticity
        axis = cross(self.H, self.tropism)
        n = norm(axis)
        if e == 0.0 or n < 1e-12:
            return
        self._rotate(rotation(tuple(c / n for c in axis), radians=e * n))


TURNS = "+-&^/\\|$"


def draw(modules, angle=90.0, step=1.0):
    """Interprets a list of (symbol, [args]) (or a string of one-letter symbols) and returns
    the segments F draws as (x0, y0, z0, x1, y1, z1) in fgsg's axes, and the polygons
    `{ . }` fill as lists of vertices in fgsg's axes."""
    if isinstance(modules, str):
        modules = [(c, []) for c in modules]
    t, stack, segs, open_, done = Turtle(), [], [], [], []
    for symbol, args in modules:
        if symbol in "Ff":
            a, b = t.forward(args[0] if args else step)
            if symbol == "F":
                segs.append(to_fgsg(a) + to_fgsg(b))
                t.bend()
        elif symbol in TURNS:
            t.turn(symbol, args[0] if args else angle)
        elif symbol == "!":
            t.width = args[0] if args else t.width
        elif symbol == "@Tp":  # L-Py's setTropism normalises T
            t.tropism = tuple(c / norm(args) for c in from_fgsg(args))
        elif symbol == "@Ts":
            t.elasticity = args[0]
        elif symbol == "@M":  # lpfg's MoveTo: the point in the world's axes
            t.P = from_fgsg(args)
        elif symbol == "@R":  # lpfg's SetHead: H = h / |h|, L = u x H normalised, U = H x L
            h, u = from_fgsg(args[:3]), from_fgsg(args[3:])
            t.H = tuple(c / norm(h) for c in h)
            left = cross(u, t.H)
            t.L = tuple(c / norm(left) for c in left)
            t.U = cross(t.H, t.L)
        elif symbol == "[":
            stack.append(t.state())
        elif symbol == "]":
            t.restore(stack.pop())
        elif symbol == "{":
            open_.append([])
        elif symbol == "." and open_:
            open_[-1].append(to_fgsg(t.P))
        elif symbol == "}" and open_:
            done.append(open_.pop())
    return segs, done
