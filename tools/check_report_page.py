#!/usr/bin/env python3
"""Checks the page `dtoadq report` writes (index.html): that it is valid HTML (html5lib's strict
parser), self-contained (no script, nothing fetched from elsewhere), that every image and link
it names exists beside it (images as PNG files), that every in-page link has its target, and that
every figure has a caption and its numbers in a table. With --browser, it also opens the page in a
headless Chromium, and fails unless every image loaded and the screenshot is not blank.

    python3 tools/check_report_page.py REPORT/index.html [--browser]

Prints one line per problem and exits 1 when there is any."""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import zlib
from urllib.parse import urlparse, unquote

import html5lib

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def local_target(url):
    """The file an URL names relative to the page, or None for an in-page anchor."""
    parsed = urlparse(url)
    if parsed.scheme or parsed.netloc:
        return "external"
    if not parsed.path:
        return None
    return unquote(parsed.path)


def check_document(page):
    problems = []
    folder = os.path.dirname(os.path.abspath(page))
    with open(page, "rb") as f:
        text = f.read()
    parser = html5lib.HTMLParser(strict=True, namespaceHTMLElements=False)
    try:
        document = parser.parse(text)
    except html5lib.html5parser.ParseError as e:
        return [f"{page}: not valid HTML: {e}"]
    ids = {e.get("id") for e in document.iter() if e.get("id")}
    for element in document.iter():
        tag = element.tag
        if tag == "script":
            problems.append(f"{page}: a <script>: the page must work without one")
        for attribute in ("src", "href"):
            url = element.get(attribute)
            if url is None:
                continue
            if url.startswith("#"):
                if url[1:] not in ids:
                    problems.append(f"{page}: <{tag} {attribute}=\"{url}\">: no element has that id")
                continue
            target = local_target(url)
            if target == "external":
                problems.append(f"{page}: <{tag} {attribute}=\"{url}\">: the page must be self-contained")
                continue
            path = os.path.join(folder, target)
            if not os.path.isfile(path) or os.path.getsize(path) == 0:
                problems.append(f"{page}: <{tag} {attribute}=\"{url}\">: no such file beside the page")
            elif tag == "img":
                with open(path, "rb") as f:
                    if f.read(8) != PNG_SIGNATURE:
                        problems.append(f"{page}: <img src=\"{url}\">: not a PNG file")
        if tag == "img" and not element.get("alt"):
            problems.append(f"{page}: <img src=\"{element.get('src')}\"> has no alt text")
        if tag == "figure":
            caption = element.find("figcaption")
            if caption is None or not "".join(caption.itertext()).strip():
                problems.append(f"{page}: a figure without a caption")
            if element.find(".//table") is None:
                problems.append(f"{page}: a figure without its numbers in a table")
    if not any(e.tag == "figure" for e in document.iter()):
        problems.append(f"{page}: no figure at all")
    return problems


def png_pixels(path):
    """Width, height and the rows of an 8-bit RGB or RGBA PNG (what Chromium writes), unfiltered."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != PNG_SIGNATURE:
        raise ValueError("not a PNG")
    pos, idat = 8, b""
    while pos < len(data):
        length = int.from_bytes(data[pos:pos + 4], "big")
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height = int.from_bytes(body[0:4], "big"), int.from_bytes(body[4:8], "big")
            depth, colour, interlace = body[8], body[9], body[12]
            if depth != 8 or colour not in (2, 6) or interlace != 0:
                raise ValueError("not an 8-bit RGB(A) PNG without interlacing")
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b = previous[x]
            c = previous[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        previous = line
    return width, height, channels, rows


def find_browser():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def check_in_browser(page):
    browser = find_browser()
    if browser is None:
        return [f"{page}: no headless browser (chromium) to open it in; install chromium"]
    problems = []
    url = "file://" + os.path.abspath(page)
    with tempfile.TemporaryDirectory() as scratch:
        common = [browser, "--headless", "--no-sandbox", "--disable-gpu", "--allow-file-access-from-files",
                  f"--user-data-dir={scratch}/profile", "--virtual-time-budget=5000"]
        # every <img> counted once the page has loaded: complete and of a natural width above 0
        probe = ("<script>addEventListener('load',()=>{const i=[...document.images];"
                 "document.title=i.filter(x=>x.complete&&x.naturalWidth>0).length+'/'+i.length;});</script>")
        probed = os.path.join(os.path.dirname(os.path.abspath(page)), ".browser_probe.html")
        with open(page, encoding="utf-8") as f:
            html = f.read()
        with open(probed, "w", encoding="utf-8") as f:
            f.write(html.replace("</head>", probe + "</head>", 1))
        try:
            dom = subprocess.run(common + ["--dump-dom", "file://" + probed], capture_output=True, text=True, timeout=120)
        finally:
            os.remove(probed)
        title = dom.stdout.split("<title>", 1)[-1].split("</title>", 1)[0] if "<title>" in dom.stdout else ""
        loaded, _, total = title.partition("/")
        if dom.returncode != 0 or not total:
            problems.append(f"{page}: the browser did not load it (exit {dom.returncode}): {dom.stderr.strip()[-200:]}")
        elif loaded != total:
            problems.append(f"{page}: the browser loaded {loaded} of its {total} images")
        shot = os.path.join(scratch, "page.png")
        run = subprocess.run(common + ["--window-size=1280,2000", f"--screenshot={shot}", url], capture_output=True, text=True, timeout=120)
        if run.returncode != 0 or not os.path.isfile(shot):
            return problems + [f"{page}: the browser made no screenshot (exit {run.returncode})"]
        width, height, channels, rows = png_pixels(shot)
        colours = set()
        for row in rows[::8]:
            for x in range(0, width * channels, channels * 8):
                colours.add(row[x:x + 3])
        if len(colours) < 16:
            problems.append(f"{page}: the browser's screenshot is blank ({len(colours)} colours)")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("page")
    parser.add_argument("--browser", action="store_true", help="also open it in headless Chromium")
    args = parser.parse_args()
    if not os.path.isfile(args.page):
        print(f"{args.page}: no such file", file=sys.stderr)
        return 1
    problems = check_document(args.page)
    if args.browser and not problems:
        problems += check_in_browser(args.page)
    for p in problems:
        print(p, file=sys.stderr)
    if not problems:
        print(f"{args.page}: valid, self-contained, every image and link present" + (", renders in Chromium" if args.browser else ""))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
