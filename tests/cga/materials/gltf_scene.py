"""Reading fgsg's glTF scenes in the CGA material tests (run_materials.py, run_layers.py)."""


def leaves(doc):
    """Node name (without CGA's trailing '.') -> the primitives in its subtree."""
    out = {}

    def visit(k, name):
        node = doc["nodes"][k]
        name = node.get("name", name)
        if "mesh" in node:
            out.setdefault(name.rstrip("."), []).extend(doc["meshes"][node["mesh"]]["primitives"])
        for c in node.get("children", []):
            visit(c, name)

    for root in doc["scenes"][0]["nodes"]:
        visit(root, "")
    return out
