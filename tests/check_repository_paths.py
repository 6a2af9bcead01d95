#!/usr/bin/env python3
"""Fails when a repository path named in a doc or in a source comment does not exist.

Scans README.md, docs/*.md (their text and their relative links) and the comments of the source
files (C, C++, OpenCL, CMake, Python, shell) for tokens that start with a top-level folder of the
repository and a slash (`render/film_resolve.cpp`, `kernels/lights/`), and checks that each names
a file or a folder. A token without an extension may name the files of a pair (`render/renderer`
for renderer.hpp and renderer.cpp); a token with `*`, `<placeholder>` or a NAME in capitals is a
pattern that must match at least one path. A moved or renamed file then fails here until every doc
and comment that names it follows it. Before it scans, it checks on a small tree of its own that it
finds broken references of each kind.

Usage: check_repository_paths.py [REPOSITORY_ROOT]   (default: the folder above this script)
Prints one line per missing path, FILE:LINE: PATH, and exits 1 if there is any.
"""
import glob
import os
import re
import sys
import tempfile

# Top-level folders whose paths are checked: these, and any other folder at the top level, so a
# reference into a removed folder still fails.
KNOWN_TOP_LEVEL = {
    "brdf", "cli", "cmake", "common", "docs", "envmaps", "film", "fit", "fuzz", "ibl", "kernels",
    "opencl", "plots", "presets", "render", "scene", "scenes", "sdf", "single_source", "tests",
    "tools", "validation", "viewer",
}

# Names that are no file in the source tree, each with why it is named.
NOT_IN_THE_SOURCE_TREE = {
    # The compiled scene's two headers, which kernels/host/scene_kernel_source.cpp serves to the kernel build.
    "scene/generated.h": "virtual header: the compiled scene's distance field",
    "scene/materials.h": "virtual header: the compiled scene's BRDF feature switches",
    # Generated in the build folder by cmake/WriteBuildInfo.cmake at every build.
    "cli/build_info.hpp": "generated header: the commit and compiler dtoadq report names",
    # Example names of a user's files, in the error messages and commands the docs show.
    "presets/mine.json": "a user's preset in docs/materials.md's error examples",
    "presets/nope.json": "a missing preset in docs/scenes.md's error examples",
    "scenes/x.json": "a user's scene in docs/scenes.md's error examples",
    "scenes/my.json": "a scene the viewer exports to, in docs/viewer.md's example",
    # Names given to text that never is a file.
    "scenes/fuzz.json": "the file name the scene fuzzer gives its input",
    "kernels/broken.cl": "an in-memory kernel source of tests/test_opencl_agreement.cpp",
}

# Folders never scanned besides hidden ones, build*/ and any build tree (a CMakeCache.txt): the
# fuzzing corpus (inputs, not prose).
SKIPPED_FOLDERS = ("fuzz/corpus",)

C_LIKE = (".cpp", ".hpp", ".h", ".cl", ".c")
HASH_COMMENTS = (".cmake", ".py", ".sh")

PATH_TOKEN = re.compile(r"(?<![\w./$-])([A-Za-z_][\w-]*)/([\w.*<>{}-][\w.*<>{}/-]*)")
MARKDOWN_LINK = re.compile(r"\]\(([^)#\s]+)")
TRAILING = ".,:;)/'\"`"


def c_comments(text):
    """(line number, comment text) of every // and /* */ comment, outside string literals."""
    out = []
    i, line, n = 0, 1, len(text)
    while i < n:
        ch = text[i]
        if ch == "\n":
            line += 1
            i += 1
        elif ch == '"' or ch == "'":
            # A string or character literal: skip to its end (raw strings are rare and
            # comment-free in this repository).
            j = i + 1
            while j < n and text[j] != ch and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            i = j + 1
        elif text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append((line, text[i:j]))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            for k, part in enumerate(text[i:j].split("\n")):
                out.append((line + k, part))
            line += text.count("\n", i, j)
            i = j
        else:
            i += 1
    return out


def hash_comments(text):
    out = []
    for number, row in enumerate(text.split("\n"), 1):
        at = row.find("#")
        if at >= 0 and not row.startswith("#!"):
            out.append((number, row[at:]))
    return out


def all_lines(text):
    return list(enumerate(text.split("\n"), 1))


def exists(root, path):
    if path in NOT_IN_THE_SOURCE_TREE:
        return True
    full = os.path.join(root, path)
    # A placeholder in capitals (fuzz/corpus/NAME) stands for any name.
    path = "/".join("*" if re.fullmatch(r"[A-Z][A-Z_]+", part) else part for part in path.split("/"))
    if re.search(r"[*<{]", path):
        pattern = re.sub(r"<[^>]*>", "*", path)
        pattern = re.sub(r"\{[^}]*\}", "*", pattern)
        return bool(glob.glob(os.path.join(root, pattern)))
    if os.path.exists(full):
        return True
    # A stem naming the files of a pair: render/renderer -> renderer.hpp, renderer.cpp.
    return "." not in os.path.basename(path) and bool(glob.glob(glob.escape(full) + ".*"))


def scanned_files(root):
    yield "README.md", all_lines
    for name in sorted(os.listdir(os.path.join(root, "docs"))):
        if name.endswith(".md"):
            yield os.path.join("docs", name), all_lines
    for folder, dirs, files in os.walk(root):
        rel = os.path.relpath(folder, root)
        dirs[:] = sorted(d for d in dirs
                         if not d.startswith(".") and not (rel == "." and d.startswith("build"))
                         and not os.path.exists(os.path.join(folder, d, "CMakeCache.txt"))
                         and os.path.normpath(os.path.join(rel, d)) not in SKIPPED_FOLDERS)
        for name in sorted(files):
            path = os.path.normpath(os.path.join(rel, name))
            if name.endswith(C_LIKE):
                yield path, c_comments
            elif name.endswith(HASH_COMMENTS) or name == "CMakeLists.txt":
                yield path, hash_comments


def missing_paths(root):
    """([FILE:LINE: PATH for each path that names nothing], how many paths were checked)."""
    top_level = KNOWN_TOP_LEVEL | {d for d in os.listdir(root)
                                   if os.path.isdir(os.path.join(root, d)) and not d.startswith(".")
                                   and not d.startswith("build")
                                   and not os.path.exists(os.path.join(root, d, "CMakeCache.txt"))}
    missing, checked = [], 0
    for path, comments in scanned_files(root):
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
            text = f.read()
        for number, comment in comments(text):
            for match in PATH_TOKEN.finditer(comment):
                if match.group(1) not in top_level:
                    continue
                token = (match.group(1) + "/" + match.group(2)).rstrip(TRAILING)
                if "/" not in token:
                    continue
                checked += 1
                if not exists(root, token):
                    missing.append(f"{path}:{number}: {token}")
            if path.endswith(".md"):
                # Markdown links are relative to the doc's own folder: [bdpt.md](bdpt.md).
                for match in MARKDOWN_LINK.finditer(comment):
                    target = match.group(1)
                    if re.match(r"[a-z]+:", target):
                        continue
                    checked += 1
                    linked = os.path.normpath(os.path.join(os.path.dirname(path), target))
                    if not os.path.exists(os.path.join(root, linked)):
                        missing.append(f"{path}:{number}: {target} (link)")
    return missing, checked


def scanner_finds_broken_paths():
    """The check must be able to fail: a small tree with one good and one broken reference of each
    kind (doc text, doc link, C++ comment, CMake comment; a path inside a string is no comment)."""
    with tempfile.TemporaryDirectory() as root:
        def write(path, text):
            os.makedirs(os.path.dirname(os.path.join(root, path)), exist_ok=True)
            with open(os.path.join(root, path), "w") as f:
                f.write(text)
        write("README.md", "See `render/film.cpp` and `render/gone.cpp`.\n")
        write("docs/a.md", "[b](b.md), [c](c.md), render/film\n")
        write("docs/b.md", "")
        write("render/film.cpp", 'const char* s = "render/not_a_comment.cpp";\n// render/film.cpp\n/* x\n kernels/gone.h */\n')
        write("render/CMakeLists.txt", "\x23 render/film.cpp render/gone.cmake\n")  # \x23: "#", so that this line is no comment
        missing, _ = missing_paths(root)
        expected = ["README.md:1: render/gone.cpp", "docs/a.md:1: c.md (link)", "render/CMakeLists.txt:1: render/gone.cmake",
                    "render/film.cpp:4: kernels/gone.h"]
        if sorted(missing) != sorted(expected):
            print("the scanner itself is broken: found", missing, "expected", expected)
            return False
    return True


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1
                           else os.path.join(os.path.dirname(__file__), ".."))
    if not scanner_finds_broken_paths():
        return 1
    missing, checked = missing_paths(root)
    for row in missing:
        print(row)
    if missing:
        print(f"{len(missing)} of {checked} repository paths named in docs and comments do not exist")
        return 1
    print(f"all {checked} repository paths named in docs and comments exist")
    return 0


if __name__ == "__main__":
    sys.exit(main())
