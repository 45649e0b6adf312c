#!/usr/bin/env python3
"""Checks an SVG written by ncurve: well-formed XML and nothing outside the page (texts by an
estimate of their width, circles, polylines and the points of paths). Prints, one a line, how
many elements carry each class, then `text CLASS: TEXT` for every classed text. Exit 1 if the
file does not parse or something is drawn off the page."""
import re
import sys
import xml.dom.minidom

NS = "{http://www.w3.org/2000/svg}"


def main(path):
    doc = xml.dom.minidom.parse(path)
    svg = doc.documentElement
    width, height = float(svg.getAttribute("width")), float(svg.getAttribute("height"))
    problems, classes, texts = [], {}, []

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
            x, y = float(el.getAttribute("x")), float(el.getAttribute("y"))
            if el.getAttribute("transform").startswith("rotate(-90"):
                inside(x - size, y - w / 2, f"text '{body}'")
                inside(x, y + w / 2, f"text '{body}'")
                continue
            anchor = el.getAttribute("text-anchor") or "start"
            x0 = x - w / 2 if anchor == "middle" else x - w if anchor == "end" else x
            inside(x0, y - size * 0.8, f"text '{body}'")
            inside(x0 + w, y, f"text '{body}'")
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
    for cls in sorted(classes):
        print(f"{cls}={classes[cls]}")
    print("\n".join(texts))
    for p in problems[:10]:
        print("OFF PAGE:", p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
