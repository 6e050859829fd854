#!/usr/bin/python3
"""Reads back a picture of a plot with the programs a user's machine has: pdfinfo, pdftotext
and pdftoppm (poppler) for PDF, svgelements and rsvg-convert for SVG.

    check_picture.py pdf FILE --title T --size WxH [--text S ...] [--equal-scales]
    check_picture.py svg FILE --title T --size WxH [--text S ...]

pdf: the document has exactly one page of W x H pt, the title T and a creator "Camwright
VERSION"; its text layer holds every S (text as text: a vector PDF, not a picture in a PDF);
rendered at 36 dpi it is not blank. --equal-scales: the tick labels of the x axis (along the
bottom) and of the y axis (along the left) are numbers placed linearly, and one mm is as long on
both (to 1 %), as a drawing of the contour must be.
svg: the viewBox is W x H and the physical size W x H pt (one user unit a point); the <title> is T; every S is the text of a <text>;
the document has strokes in at least three colours; rsvg-convert renders it.
Prints what it found; exits 1 on the first failure.
"""
import argparse
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def run(*args):
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout


def numbers_along(words, key_value, key_pos):
    """(value, position) of the words that are numbers."""
    out = []
    for w in words:
        try:
            out.append((float(w["text"].replace("\u2212", "-")), key_pos(w)))
        except ValueError:
            pass
    return out


def linear_fit(pairs):
    n = len(pairs)
    mx = sum(v for v, _ in pairs) / n
    my = sum(p for _, p in pairs) / n
    sxx = sum((v - mx) ** 2 for v, _ in pairs)
    slope = sum((v - mx) * (p - my) for v, p in pairs) / sxx
    worst = max(abs(my + slope * (v - mx) - p) for v, p in pairs)
    return slope, worst


def check_pdf(args, w, h):
    info = run("pdfinfo", args.file)
    fields = dict(
        (line.split(":", 1)[0].strip(), line.split(":", 1)[1].strip())
        for line in info.splitlines() if ":" in line)
    print("pdfinfo:", fields.get("Title"), "|", fields.get("Creator"), "|",
          fields.get("Page size"), "|", fields.get("Pages"))
    if fields.get("Pages") != "1":
        fail("pages: %s" % fields.get("Pages"))
    size = re.match(r"([\d.]+) x ([\d.]+) pts", fields.get("Page size", ""))
    if not size or abs(float(size.group(1)) - w) > 0.5 or abs(float(size.group(2)) - h) > 0.5:
        fail("page size %r, expected %d x %d pts" % (fields.get("Page size"), w, h))
    if fields.get("Title") != args.title:
        fail("title %r, expected %r" % (fields.get("Title"), args.title))
    if not re.fullmatch(r"Camwright \d+\.\d+\.\d+", fields.get("Creator", "")):
        fail("creator %r" % fields.get("Creator"))
    text = run("pdftotext", args.file, "-")
    for s in args.text:
        if s not in text:
            fail("text %r not in the text layer: %r" % (s, text[:400]))
    with tempfile.TemporaryDirectory() as d:
        subprocess.run(["pdftoppm", "-r", "36", "-gray", args.file, d + "/page"], check=True)
        import glob
        pgm = open(glob.glob(d + "/page*.pgm")[0], "rb").read()
        # P5 header: magic, width, height, maxval, then one byte per pixel
        parts = pgm.split(maxsplit=4)
        pw, ph = int(parts[1]), int(parts[2])
        pixels = parts[4][:pw * ph]
        dark = sum(1 for b in pixels if b < 200)
        print("rendered %dx%d, %d dark pixels" % (pw, ph, dark))
        if dark < 0.01 * pw * ph:
            fail("the rendered page is (nearly) blank")
    if args.equal_scales:
        html = run("pdftotext", "-bbox", args.file, "-")
        words = [dict(xMin=float(m.group(1)), yMin=float(m.group(2)), xMax=float(m.group(3)),
                      yMax=float(m.group(4)), text=m.group(5))
                 for m in re.finditer(r'<word xMin="([\d.]+)" yMin="([\d.]+)" xMax="([\d.]+)" '
                                      r'yMax="([\d.]+)">([^<]*)</word>', html)]
        bottom = [x for x in words if x["yMin"] > 0.85 * h and x["xMin"] > 0.12 * w]
        left = [x for x in words if x["xMax"] < 0.12 * w]
        xs = numbers_along(bottom, None, lambda x: (x["xMin"] + x["xMax"]) / 2)
        ys = numbers_along(left, None, lambda x: (x["yMin"] + x["yMax"]) / 2)
        if len(xs) < 3 or len(ys) < 3:
            fail("too few tick labels: x %r, y %r" % (xs, ys))
        sx, wx = linear_fit(xs)
        sy, wy = linear_fit(ys)
        print("x: %.4f pt/mm (worst label off by %.2f pt); y: %.4f pt/mm (%.2f pt)" % (sx, wx, sy, wy))
        if wx > 1.5 or wy > 1.5:
            fail("tick labels are not placed linearly")
        if sx <= 0 or sy >= 0:
            fail("x must grow to the right and y upwards")
        if abs(sx + sy) > 0.01 * sx:
            fail("one mm is %.4f pt along x but %.4f pt along y" % (sx, -sy))


def check_svg(args, w, h):
    import svgelements
    svg = svgelements.SVG.parse(args.file)
    print("svg: %s x %s, viewbox %s" % (svg.width, svg.height, svg.viewbox))
    # One user unit is a point: the physical size is W x H pt, which svgelements gives in CSS
    # pixels (96 per inch, 72 points per inch).
    if abs(svg.width - w * 96 / 72) > 0.5 or abs(svg.height - h * 96 / 72) > 0.5:
        fail("size %s x %s px, expected %d x %d pt" % (svg.width, svg.height, w, h))
    if svg.viewbox is None or abs(svg.viewbox.width - w) > 0.5 or abs(svg.viewbox.height - h) > 0.5:
        fail("viewBox %s" % svg.viewbox)
    ns = {"s": "http://www.w3.org/2000/svg"}
    root = ET.parse(args.file).getroot()
    title = root.find("s:title", ns)
    if title is None or title.text != args.title:
        fail("title %r, expected %r" % (None if title is None else title.text, args.title))
    texts = ["".join(t.itertext()) for t in root.iter("{http://www.w3.org/2000/svg}text")]
    for s in args.text:
        if not any(s in t for t in texts):
            fail("no <text> holds %r (texts: %r)" % (s, texts[:20]))
    colours = set()
    for element in svg.elements():
        stroke = getattr(element, "stroke", None)
        if stroke is not None and stroke.value is not None and isinstance(element, svgelements.Shape):
            colours.add(str(stroke))
    print("stroke colours:", len(colours))
    if len(colours) < 3:
        fail("fewer than three stroke colours: %r" % colours)
    with tempfile.TemporaryDirectory() as d:
        subprocess.run(["rsvg-convert", "-o", d + "/out.png", args.file], check=True)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("kind", choices=["pdf", "svg"])
    parser.add_argument("file")
    parser.add_argument("--title", required=True)
    parser.add_argument("--size", required=True)
    parser.add_argument("--text", action="append", default=[])
    parser.add_argument("--equal-scales", action="store_true")
    args = parser.parse_args()
    w, h = (int(v) for v in args.size.split("x"))
    if args.kind == "pdf":
        check_pdf(args, w, h)
    else:
        check_svg(args, w, h)
    print("OK")


if __name__ == "__main__":
    main()
