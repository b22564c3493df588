#!/usr/bin/env python3
"""Writes fuzz/seeds/sidecar/slim_*.json: the book figures' sidecars cut down
to seeds for fuzz_sidecar (run from the repository root; commit the output).

The sidecars themselves are 6 KiB to 4 MiB, almost all of it vertices, label
text and measurements the reader treats alike, and their textures are remade
at 256 or 640 texels a side on every execution.  A seed here keeps every key
and every kind of value the figure has (the same reader paths), but at most 2
panels of 2 batches of 3 vertices (and a third panel or batch if only it has
uniforms), 3 textures, 3 labels and 3 state entries, numbers to 3 digits,
textures remade at 16 texels a side, no measurements or prose, on one line:
0.2 to 3.5 KiB, under fuzz/run.sh's max_len for the target (4 KiB).

A figure whose textures are rendered by a demo (generator *_render, which the
reader cannot remake: it stops at textures[0]) also gives a second seed with
those textures replaced by a small gradient, so that the reader's panels,
batches and labels are reached from its shape too.  The fuzzer's regressions
(fuzz/regressions/sidecar/) are cut down the same way, and four hand-written
seeds cover what no figure uses: a 'file' and a 'texel_index' texture, the
optional batch keys (texture matrix, tex_env colour, colour sum, secondary
colours) with points, and a document with only the required keys.
"""
import glob
import json
import os

OUT = "fuzz/seeds/sidecar"
KNOWN = {"checkerboard", "texel_index", "labelled_grid", "mip_level_colours", "gradient", "file"}
SMALL = 16


def rounded(v):
    if isinstance(v, float):
        return float(f"{v:.3g}")
    if isinstance(v, list):
        return [rounded(x) for x in v]
    if isinstance(v, dict):
        return {k: rounded(x) for k, x in v.items()}
    return v


def small_texture(t):
    t = dict(t)
    p = dict(t.get("params", {}))
    name = t.get("name")
    if name in ("checkerboard", "labelled_grid", "mip_level_colours", "texel_index") and "size" in p:
        p["size"] = str(SMALL)
        if name == "checkerboard":
            p["checks"] = str(min(int(p.get("checks", "2")), SMALL))
        t["width"] = t["height"] = SMALL
    if name == "gradient":
        p["width"] = str(min(int(p.get("width", "4")), SMALL))
        p["height"] = str(min(int(p.get("height", "4")), SMALL))
        t["width"], t["height"] = int(p["width"]), int(p["height"])
    t["params"] = p
    return t


def gradient_like(t):
    g = dict(t)
    g["name"] = "gradient"
    g["params"] = {"width": "4", "height": "4", "alpha": "opaque"}
    g["width"] = g["height"] = 4
    if g.get("mipmaps") == "explicit":
        g["mipmaps"] = "box_2x2"
    return g


def slim(doc):
    out = {}
    for k, v in doc.items():
        if k in ("caption", "command", "measurements", "conventions"):
            continue
        if k == "state":
            v = dict(list(v.items())[:3])
        elif k == "panels":
            panels = []
            # the first two panels, and a third if only it has uniforms
            keep = v[:2] + [p for p in v[2:] if any(b.get("uniforms") for b in p.get("batches", []))][:1]
            for p in keep:
                p = dict(p)
                batches = []
                batches_in = p.get("batches", [])
                for b in batches_in[:2] + [b for b in batches_in[2:] if b.get("uniforms")][:1]:
                    b = dict(b)
                    b["vertices"] = b.get("vertices", [])[:3]
                    if isinstance(b.get("texture"), int) and b["texture"] >= min(len(doc.get("textures", [])), 3):
                        b["texture"] = 0
                    batches.append(b)
                p["batches"] = batches
                panels.append(p)
            v = panels
        elif k == "labels":
            v = [dict(l, text=l.get("text", "")[:12]) for l in v[:3]]
        elif k == "textures":
            v = [small_texture(t) for t in v[:3]]
        out[k] = v
    return rounded(out)


def write(name, doc):
    text = json.dumps(doc, separators=(",", ":"))
    with open(os.path.join(OUT, name), "w") as f:
        f.write(text + "\n")
    return len(text) + 1


def main():
    os.makedirs(OUT, exist_ok=True)
    for old in glob.glob(os.path.join(OUT, "slim_*.json")):
        os.remove(old)
    sizes = {}
    for path in sorted(glob.glob("book_figures/*.json")):
        if os.path.getsize(path) > 64 * 1024:
            continue  # the figures fuzz/run.sh used as seeds before (< 64 KiB)
        base = os.path.splitext(os.path.basename(path))[0]
        doc = slim(json.load(open(path)))
        sizes[base] = write(f"slim_{base}.json", doc)
        if any(t.get("name") not in KNOWN for t in doc.get("textures", [])):
            doc = dict(doc, textures=[t if t.get("name") in KNOWN else gradient_like(t) for t in doc["textures"]])
            sizes[base + "_remade"] = write(f"slim_{base}_remade.json", doc)
    # The fuzzer's regressions (whole numbers of 1e300), cut down the same way.
    for path in sorted(glob.glob("fuzz/regressions/sidecar/*.json")):
        base = os.path.splitext(os.path.basename(path))[0]
        sizes["regression_" + base] = write(f"slim_regression_{base}.json", slim(json.load(open(path))))
    # What no figure has.
    base = json.load(open(os.path.join(OUT, "slim_texture_matrix.json")))
    tex = dict(base["textures"][0], name="file", params={"path": "no/such/picture.png"})
    sizes["file"] = write("slim_hand_file_texture.json", dict(base, textures=[tex]))
    panel = dict(base["panels"][0])
    b = dict(panel["batches"][0], primitive="points", tex_env="GL_BLEND", tex_env_color=[0.5, 0.25, 0, 1],
             texture_matrix=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5, 0, 0, 1], color_sum=True)
    b.pop("point_size", None)
    b["vertices"] = [dict(v, secondary=[0.1, 0.2, 0.3]) for v in b["vertices"]]
    sizes["batch_keys"] = write("slim_hand_batch_keys.json", dict(base, panels=[dict(panel, batches=[b])]))
    tex = dict(base["textures"][0], name="texel_index", params={"size": "4"}, width=4, height=4, mipmaps=False)
    sizes["texel_index"] = write("slim_hand_texel_index.json", dict(base, textures=[tex]))
    lean = {"size": [4, 4], "textures": [], "panels": [{"viewport": [0, 0, 4, 4], "projection": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1],
            "modelview": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], "batches": []}], "labels": [{"x": 1, "y": 2, "text": "a"}]}
    sizes["lean"] = write("slim_hand_lean.json", lean)
    print(f"{len(sizes)} seeds, {min(sizes.values())}..{max(sizes.values())} bytes, {sum(sizes.values())} in all")


if __name__ == "__main__":
    main()
