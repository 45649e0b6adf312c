#!/usr/bin/env python3
"""Checks an SVG written by ncurve: well-formed XML, nothing outside the page (texts by an
estimate of their box, circles, polylines and the points of paths) and no two texts overlapping.
A text's box is estimated as the plotting layer does (src/report/svg_plot.cpp): 0.62 em a
character across, from 0.8 em above its baseline to 0.2 em below. Prints, one a line, how many
elements carry each class, then `text CLASS: TEXT` for every classed text. Exit 1 if the file
does not parse, something is drawn off the page or two texts overlap."""
import re
import sys
import xml.dom.minidom

NS = "{http://www.w3.org/2000/svg}"


def main(path):
    doc = xml.dom.minidom.parse(path)
    svg = doc.documentElement
    width, height = float(svg.getAttribute("width")), float(svg.getAttribute("height"))
    problems, classes, texts, boxes = [], {}, [], []

    def inside(x, y, what):
        if not (-0.5 <= x <= width + 0.5 and -0.5 <= y <= height + 0.5):
            problems.append(f"{what} at ({x:.1f}, {y:.1f}) is off the {width:g} x {height:g} page")

    for el in svg.getElementsByTagName("*"):
        cls = el.getAttribute("class")
        if cls:
            classes[cls] = classes.get(cls, 0) + 1
        tag = el.tagName
        if tag == "text":
            body = "".join(n.data for n in el.childNodes if n.nodeType == n.TEXT_NODE)
            if cls:
                texts.append(f"text {cls}: {body}")
            size = float(el.getAttribute("font-size") or 12)
            w = len(body) * size * 0.62
            x, y = float(el.getAttribute("x")), float(el.getAttribute("y")) + float(el.getAttribute("dy") or 0)
            anchor = el.getAttribute("text-anchor") or "start"
            if el.getAttribute("transform").startswith("rotate(-90"):
                # turned about (x, y): along the text is up the page, the baseline on the right
                y0 = y - w / 2 if anchor == "middle" else y - w if anchor == "start" else y
                box = (x - size * 0.8, y0, x + size * 0.2, y0 + w)
            else:
                x0 = x - w / 2 if anchor == "middle" else x - w if anchor == "end" else x
                box = (x0, y - size * 0.8, x0 + w, y + size * 0.2)
            inside(box[0], box[1], f"text '{body}'")
            inside(box[2], box[3], f"text '{body}'")
            if body.strip():
                boxes.append((box, body))
        elif tag == "circle":
            cx, cy, r = (float(el.getAttribute(a)) for a in ("cx", "cy", "r"))
            inside(cx - r, cy - r, "circle")
            inside(cx + r, cy + r, "circle")
        elif tag in ("polyline", "polygon"):
            nums = [float(v) for v in re.findall(r"-?[0-9.]+", el.getAttribute("points"))]
            for x, y in zip(nums[::2], nums[1::2]):
                inside(x, y, tag)
        elif tag == "path":
            for x, y in re.findall(r"[ML](-?[0-9.]+),(-?[0-9.]+)", el.getAttribute("d")):
                inside(float(x), float(y), f"path {cls}")
    # every pair of texts, by their boxes less half a pixel each way (the estimate is generous)
    boxes.sort(key=lambda b: b[0][0])
    for i, (a, ta) in enumerate(boxes):
        for b, tb in boxes[i + 1:]:
            if b[0] >= a[2] - 1:
                break
            if min(a[3], b[3]) - max(a[1], b[1]) > 1:
                problems.append(f"text '{ta}' at ({a[0]:.1f}, {a[1]:.1f}) overlaps '{tb}' at ({b[0]:.1f}, {b[1]:.1f})")
    for cls in sorted(classes):
        print(f"{cls}={classes[cls]}")
    print("\n".join(texts))
    for p in problems[:10]:
        print("PROBLEM:", p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
