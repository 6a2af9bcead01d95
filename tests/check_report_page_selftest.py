#!/usr/bin/env python3
"""tools/check_report_page.py must fail on broken pages: each broken variant of a small valid page
(a missing image, a file that is not a PNG, an unclosed element, a link elsewhere, a script, a
figure without caption or table, an anchor without target, an image the browser cannot decode)
is flagged, and the valid page passes, in the browser too when --browser is given."""
import os
import subprocess
import sys
import tempfile
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
CHECKER = os.path.join(HERE, "..", "tools", "check_report_page.py")


def png(width, height):
    def chunk(kind, body):
        return len(body).to_bytes(4, "big") + kind + body + zlib.crc32(kind + body).to_bytes(4, "big")
    rows = b"".join(b"\x00" + bytes(c for x in range(width) for c in (x * 7 % 256, y * 5 % 256, (x + y) % 256)) for y in range(height))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", width.to_bytes(4, "big") + height.to_bytes(4, "big") + b"\x08\x02\x00\x00\x00")
            + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


GOOD = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>t</title></head><body>
<nav><a href="#s">s</a></nav>
<section id="s"><h2>s</h2>
<figure><img src="a.png" alt="a"><table><tr><td>1</td></tr></table><figcaption>A caption.</figcaption></figure>
<p><a href="a.csv">a.csv</a></p>
</section></body></html>
"""

BROKEN = {
    "missing image": GOOD.replace("a.png", "absent.png"),
    "missing csv": GOOD.replace("a.csv\"", "absent.csv\""),
    "unclosed element": GOOD.replace("</figure>", "</figure></div>"),
    "link elsewhere": GOOD.replace("a.csv\"", "https://example.com/a.csv\""),
    "script": GOOD.replace("</body>", "<script>1</script></body>"),
    "no caption": GOOD.replace("<figcaption>A caption.</figcaption>", ""),
    "no table": GOOD.replace("<table><tr><td>1</td></tr></table>", ""),
    "anchor without target": GOOD.replace("#s", "#t"),
    "no alt text": GOOD.replace(' alt="a"', ""),
    "not a png": GOOD.replace("a.png", "a.csv"),
}


def check(folder, html, browser):
    with open(os.path.join(folder, "index.html"), "w") as f:
        f.write(html)
    args = [sys.executable, CHECKER, os.path.join(folder, "index.html")] + (["--browser"] if browser else [])
    return subprocess.run(args, capture_output=True, text=True)


def main():
    browser = "--browser" in sys.argv
    failures = []
    with tempfile.TemporaryDirectory() as folder:
        with open(os.path.join(folder, "a.png"), "wb") as f:
            f.write(png(64, 48))
        with open(os.path.join(folder, "a.csv"), "w") as f:
            f.write("x\n1\n")
        good = check(folder, GOOD, browser)
        if good.returncode != 0:
            failures.append(f"the valid page was refused: {good.stderr.strip()}")
        for name, html in BROKEN.items():
            r = check(folder, html, False)
            if r.returncode == 0:
                failures.append(f"not flagged: {name}")
        if browser:
            # a PNG signature over garbage passes the file checks, and only the browser sees it cannot be decoded
            with open(os.path.join(folder, "bad.png"), "wb") as f:
                f.write(b"\x89PNG\r\n\x1a\n" + b"garbage" * 10)
            r = check(folder, GOOD.replace("a.png", "bad.png"), True)
            if r.returncode == 0 or "loaded 0 of its 1 images" not in r.stderr:
                failures.append(f"not flagged in the browser: an image it cannot decode ({r.stderr.strip()})")
    for f in failures:
        print(f, file=sys.stderr)
    print(f"check_report_page: {len(BROKEN) + (2 if browser else 1) - len(failures)} of {len(BROKEN) + (2 if browser else 1)} cases right")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
