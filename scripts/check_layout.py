#!/usr/bin/env python3
"""The include graph of src/ against the direction the pipeline allows.

The allowed folder -> folder includes are the table between the `layout:begin` and
`layout:end` markers of docs/pipeline.md, so the page and this check cannot disagree.
Every `#include "folder/..."` of a file in src/ must name its own folder or one its row
allows; public headers (`velocity/...`) may be included from anywhere. A folder of src/
missing from the table, or a row naming a folder that does not exist, fails too.

  scripts/check_layout.py [REPO]    exit status 0: the layout holds; 1: the violations
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"/]+)/[^"]+"', re.MULTILINE)
SOURCES = (".cpp", ".hpp", ".h")
TOP = "src"  # the files directly in src/ (the frame): a row of their own


def read_table(page: pathlib.Path) -> dict[str, set[str]]:
    text = page.read_text()
    begin, end = text.find("<!-- layout:begin -->"), text.find("<!-- layout:end -->")
    if begin < 0 or end < begin:
        sys.exit(f"{page}: no <!-- layout:begin --> ... <!-- layout:end --> table")
    allowed = {}
    for line in text[begin:end].splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != 2 or not cells[0].startswith("`"):
            continue  # the header, its rule, the markers
        folder = re.findall(r"`([^`]+)`", cells[0])[0]
        folder = TOP if folder == "src/*.cpp" else folder.removeprefix("src/").rstrip("/")
        allowed[folder] = set(re.findall(r"`([^`]+)`", cells[1]))
    return allowed


def main() -> int:
    repo = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
    src = repo / "src"
    allowed = read_table(repo / "docs" / "pipeline.md")
    folders = {p.name for p in src.iterdir() if p.is_dir()}
    errors = []
    for folder in sorted(folders - allowed.keys()):
        errors.append(f"src/{folder}/: not in docs/pipeline.md's layout table")
    for folder in sorted(allowed.keys() - folders - {TOP}):
        errors.append(f"docs/pipeline.md's layout table: src/{folder}/ does not exist")
    for folder, targets in sorted(allowed.items()):
        for t in sorted(targets - folders):
            errors.append(f"docs/pipeline.md's layout table: {folder} may include {t}, which does not exist")
    for path in sorted(src.rglob("*")):
        if path.suffix not in SOURCES:
            continue
        rel = path.relative_to(src)
        own = rel.parts[0] if len(rel.parts) > 1 else TOP
        for match in INCLUDE.finditer(path.read_text()):
            target = match.group(1)
            if target == "velocity" or target == own or target not in folders:
                continue
            if target not in allowed.get(own, set()):
                line = path.read_text().count("\n", 0, match.start()) + 1
                errors.append(f"src/{rel}:{line}: includes {target}/ against the direction ({own} may include: "
                              f"{', '.join(sorted(allowed.get(own, set()))) or 'nothing'})")
    for e in errors:
        print(e)
    if not errors:
        print(f"layout: {sum(1 for p in src.rglob('*') if p.suffix in SOURCES)} files of src/ include along the "
              f"direction of docs/pipeline.md")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
