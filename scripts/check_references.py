#!/usr/bin/env python3
"""Fails when the docs or the code's comments name a file or folder that does not exist.

Scans README.md, docs/*.md and every tracked source file (comments and strings alike:
a path in a string is a path too) for words that look like paths inside the project —
`src/raster/bins.hpp`, `present/runtime/`, `[the pipeline](docs/pipeline.md)` — and
checks each against the tree. A path is resolved from the project root, from the
folders the build puts on the include path (src/, include/, gl/include/), from the
folder of the file that names it and each folder above it, from the folder beside the
project and from /usr/include (system headers); build outputs (build*/), ../shared/, install locations and paths with
wildcards or placeholders are not checked. A Markdown link's #fragment must name a
heading of the page it points to.

    scripts/check_references.py [ROOT]     exit 0: none stale; 1: each stale one listed
"""
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent)
TOP = ("src", "include", "gl", "present", "python", "apps", "tests", "scripts", "docs", "cmake", ".ci")
SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".c", ".py", ".pyi", ".sh", ".cmake", ".txt", ".in", ".md", ".map"}
SEARCH_ROOTS = ("", "src", "include", "gl/include", "python", "present")
# Not in the tree: where things are installed, and other projects' trees that comments
# name (Mesa's src/mesa/main/, which pGL's layout follows).
ELSEWHERE = ("include/velocity-gl/", "src/mesa/")
# A path: an optional ./, a first folder of the project (or, for include-style names, any
# folder the resolver knows), then /-separated name parts ending in a file or a slash.
PATH = re.compile(r"(?<![\w./~$-])((?:\./)?[A-Za-z_.][\w.-]*(?:/[\w.*<>{}-]+)+/?)")
MD_LINK = re.compile(r"\]\(([^)#\s]+)(?:#[^)]*)?\)")


def slug(heading):
    """GitHub's anchor for a Markdown heading: lower case, punctuation dropped, spaces to -."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


def anchors(path):
    text = path.read_text(encoding="utf-8")
    return {slug(m) for m in re.findall(r"^#+ (.+)$", text, re.MULTILINE)}


def stale_anchors(rel, line):
    """The #fragments of this line's Markdown links that name no heading."""
    for target, fragment in re.findall(r"\]\(([^)#\s]*)#([^)\s]+)\)", line):
        page = (ROOT / rel.parent / target) if target else ROOT / rel
        if page.suffix == ".md" and page.exists() and fragment not in anchors(page):
            yield f"{target}#{fragment}"


def tracked_files():
    out = subprocess.run(["git", "-C", str(ROOT), "ls-files"], capture_output=True, text=True, check=True).stdout
    for name in out.splitlines():
        p = Path(name)
        if p.parts[0] in ("tests",) and len(p.parts) > 1 and p.parts[1] in ("data", "fuzz") and p.suffix not in (".md", ".cpp", ".txt", ".sh"):
            continue
        if p.suffix in SOURCE_SUFFIXES or p.name in ("CMakeLists.txt", "run", "README.md"):
            yield p


def checkable(ref):
    if any(c in ref for c in "*<>{}$") or "..." in ref:
        return False
    first = ref.lstrip("./").split("/")[0]
    if first.startswith("build") or first == "shared" or ref.startswith(("../",) + ELSEWHERE) or "://" in ref:
        return False
    return True


def exists(ref, owner):
    ref = ref.rstrip("/").removeprefix("./")
    bases = [ROOT / base for base in SEARCH_ROOTS] + [ROOT / a for a in owner.parents]  # the file's folder and above
    bases.append(Path("/usr/include"))  # system headers (hwy/, stb/)
    return any((base / ref).exists() for base in bases)


def looks_like_project_path(ref):
    parts = ref.lstrip("./").split("/")
    if parts[0] in TOP:
        return True
    # include-style names (raster/bins.hpp, velocity/scene.hpp): a folder, then a file
    # with a source suffix
    return len(parts) >= 2 and Path(parts[-1]).suffix in (".hpp", ".h", ".cpp", ".c", ".py", ".md", ".sh")


def main():
    stale = []
    for rel in tracked_files():
        try:
            text = (ROOT / rel).read_text(encoding="utf-8")
        except (UnicodeDecodeError, FileNotFoundError):
            continue
        for lineno, line in enumerate(text.splitlines(), 1):
            refs = set(MD_LINK.findall(line)) if rel.suffix == ".md" else set()
            if rel.suffix == ".md":
                stale += [f"{rel}:{lineno}: {a}" for a in stale_anchors(rel, line)]
            refs |= {m for m in PATH.findall(line) if looks_like_project_path(m)}
            for ref in sorted(refs):
                ref = ref.rstrip(".,;:)'\"`")
                if ref.startswith(("http", "mailto:", "#")) or not checkable(ref):
                    continue
                if not exists(ref, rel):
                    stale.append(f"{rel}:{lineno}: {ref}")
    for s in stale:
        print(s)
    print(f"check_references: {len(stale)} stale reference(s)")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
