"""Result.scene(): the nodes of the glTF scene fgsg run writes (issue #45). On lots, each
start shape's node is named after its feature id and carries its properties, the attrs'
values it derived with and its reports, with the values worked out by hand; on the Müller
building the list is, node for node, what an independent reader finds in the .gltf that
`fgsg run` writes for the same seed (names, parents, transforms, extras, instances)."""
import json
import math
import os
import subprocess

import pytest

import fgsg

SOURCE = os.environ["FGSG_SOURCE"]
FGSG = os.environ["FGSG_BINARY"]
MUELLER = os.path.join(SOURCE, "examples", "mueller_building.fgsg")
IDENTITY = ((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1))

# Lot A 20 x 10 (200 m2) 12 m high, B 12 x 8 (96 m2) 5 m high.
LOTS = ('{"type": "FeatureCollection", "crs": {"type": "name", "properties": {"name": "urn:fgsg:local-metres"}},'
        ' "features": ['
        '{"type": "Feature", "id": "A", "properties": {"height": 12, "use": "shop"}, "geometry": {"type": "Polygon",'
        ' "coordinates": [[[0, 0], [20, 0], [20, 10], [0, 10], [0, 0]]]}},'
        '{"type": "Feature", "id": "B", "properties": {"height": 5}, "geometry": {"type": "Polygon",'
        ' "coordinates": [[[30, 0], [42, 0], [42, 8], [30, 8], [30, 0]]]}}]}')
GRAMMAR = ('attr height = 0;\nattr use = "none";\n'
           'Lot ~> Report("lot.area", Lot.area) Report("use", use) Extrude(height) Comp("sidefaces"){ Wall };\n'
           'Wall ~> Report("wall.area", Scope.sx * Scope.sy) W;\n')


def numbers(values):
    return {"values": values, "count": len(values), "sum": sum(values), "average": sum(values) / len(values),
            "min": min(values), "max": max(values), "nnz": sum(1 for v in values if v != 0)}


def test_start_nodes_carry_properties_attrs_and_reports(tmp_path):
    lots = tmp_path / "lots.geojson"
    lots.write_text(LOTS)
    r = fgsg.Grammar.from_text(GRAMMAR, "lots.fgsg").generate(lots=str(lots), attrs={"use": "office"})
    nodes = r.scene()
    starts = [n for n in nodes if n.parent == -1]
    assert [s.name for s in starts] == ["A", "B"]
    a, b = starts
    assert a.extras == {"start": 0, "instances": 4, "properties": {"height": 12, "use": "shop"},
                        "attrs": {"height": 12, "use": "shop"},
                        "reports": {"lot.area": numbers([200]),
                                    "use": {"values": ["shop"], "count": 1, "strings": {"shop": 1}},
                                    "wall.area": numbers([240, 120, 240, 120])}}
    # B has no "use": --set's value.
    assert b.extras == {"start": 1, "instances": 4, "properties": {"height": 5},
                        "attrs": {"height": 5, "use": "office"},
                        "reports": {"lot.area": numbers([96]),
                                    "use": {"values": ["office"], "count": 1, "strings": {"office": 1}},
                                    "wall.area": numbers([60, 40, 60, 40])}}
    assert a.transform == IDENTITY and a.instances == 4 and b.instances == 4
    # Grouped by symbol: each lot's one group W holds its four walls.
    groups = [n for n in nodes if n.parent >= 0 and nodes[n.parent].parent == -1]
    assert [(g.name, nodes[g.parent].name, g.instances) for g in groups] == [("W", "A", 4), ("W", "B", 4)]
    # Without groups, the start nodes are the lots' only nodes.
    flat = r.scene(instancing="off", group_by="none")
    assert [(n.name, n.parent, n.instances) for n in flat] == [("A", -1, 4), ("B", -1, 4)]
    assert flat[0].extras["reports"] == a.extras["reports"] and flat[0].meshes == 1


def test_bad_scene_arguments_are_value_errors(tmp_path):
    r = fgsg.Grammar.from_text(GRAMMAR, "lots.fgsg").generate(attrs={"height": 3})
    with pytest.raises(ValueError, match="instancing must be 'auto', 'on', 'nodes' or 'off', got 'yes'"):
        r.scene(instancing="yes")
    with pytest.raises(ValueError, match="group_by must be 'symbol' or 'none', got 'rule'"):
        r.scene(group_by="rule")


def gltf_nodes(path):
    """The .gltf's nodes in pre-order from the scene's roots, as (name, parent, 4x4 rows,
    extras, draws a mesh, instances): instances from extras, 1 for a node per instance."""
    doc = json.load(open(path))
    out = []

    def matrix(n):
        if "matrix" in n:
            m = n["matrix"]
            return tuple(tuple(m[4 * c + r] for c in range(4)) for r in range(4))
        x, y, z, w = n.get("rotation", (0, 0, 0, 1))
        s = n.get("scale", (1, 1, 1))
        t = n.get("translation", (0, 0, 0))
        rot = ((1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
               (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
               (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)))
        return tuple(tuple(rot[r][c] * s[c] for c in range(3)) + (t[r],) for r in range(3)) + ((0, 0, 0, 1),)

    def visit(k, parent):
        n = doc["nodes"][k]
        extras = n.get("extras", {})
        instances = extras.get("instances", 1 if "asset" in extras else 0)
        out.append((n["name"], parent, matrix(n), extras, "mesh" in n, instances))
        here = len(out) - 1
        for c in n.get("children", []):
            visit(c, here)

    for root in doc["scenes"][0]["nodes"]:
        visit(root, -1)
    return out


@pytest.mark.parametrize("instancing", ["auto", "nodes"])
def test_the_scene_is_the_gltf_fgsg_run_writes(tmp_path, instancing):
    out = tmp_path / "house.gltf"
    subprocess.run([FGSG, "run", MUELLER, "--seed", "3", "-q", "-o", str(out), "--instancing", instancing],
                   check=True)
    expected = gltf_nodes(out)
    nodes = fgsg.Grammar.from_file(MUELLER).generate(seed=3).scene(instancing=instancing)
    assert len(nodes) == len(expected) > 3
    assert any(n.parent >= 0 and n.extras.get("asset") for n in nodes)  # some shared mesh
    for n, (name, parent, matrix, extras, has_mesh, instances) in zip(nodes, expected):
        assert (n.name, n.parent, n.extras, n.meshes > 0) == (name, parent, extras, has_mesh)
        if parent >= 0 and nodes[parent].parent >= 0:  # below a group: counts of its own
            assert n.instances == instances, n
        assert all(math.isclose(a, b, rel_tol=1e-6, abs_tol=1e-6) for ra, rb in zip(n.transform, matrix)
                   for a, b in zip(ra, rb)), (n.name, n.transform, matrix)
