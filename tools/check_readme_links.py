#!/usr/bin/env python3
"""Checks that every link in the project's Markdown leads somewhere.

  tools/check_readme_links.py [FILE.md ...]   (default: README.md and docs/*.md)

A link to `#anchor` must name a heading of its file, spelled as GitHub spells its anchors
(lower case; spaces to hyphens; punctuation other than hyphens and underscores dropped; a
repeated heading gains -1, -2, ...). A link to a relative path must name a file or folder of
the checkout (relative to the linking file), and one to `FILE.md#anchor` a heading of
FILE.md. Links to the web are not followed (the tests reach nothing beyond the machine).
Code spans and fenced blocks are skipped: a command's `[...]` is not a link. Prints one line
per broken link and a closing PASS or FAIL.
"""
import argparse
import pathlib
import re
import sys

HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
LINK = re.compile(r"\[(?:[^\[\]]|\[[^\]]*\])*\]\(([^()\s]+)\)")
CODE_SPAN = re.compile(r"`+[^`]*`+")


def github_anchor(heading):
    # GitHub drops Markdown's own marks and punctuation, keeps letters, digits, '-', '_' and
    # spaces (spaces become hyphens): `--out FILE.mp4|DIR/%05d.png` gives --out-filemp4dir05dpng.
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link in a heading: its text
    text = text.replace("`", "").lower()
    text = "".join(c for c in text if c.isalnum() or c in " -_")
    return text.replace(" ", "-")


def prose_lines(lines):
    """(number, line) outside fenced code blocks."""
    fenced = False
    for number, line in enumerate(lines, start=1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if not fenced:
            yield number, line


def anchors_of(markdown):
    """The anchors of a Markdown file's headings, as GitHub makes them."""
    anchors, seen = set(), {}
    for _, line in prose_lines(markdown.read_text().splitlines()):
        match = HEADING.match(line)
        if not match:
            continue
        anchor = github_anchor(match.group(2))
        count = seen.get(anchor, 0)
        seen[anchor] = count + 1
        anchors.add(anchor if count == 0 else f"{anchor}-{count}")
    return anchors


def broken_links(markdown):
    """One line per link in `markdown` (a path) that leads nowhere, and how many were read."""
    lines = markdown.read_text().splitlines()
    base = markdown.resolve().parent
    anchors = anchors_of(markdown)
    broken, checked = [], 0
    for number, line in prose_lines(lines):
        for target in LINK.findall(CODE_SPAN.sub("", line)):
            checked += 1
            if target.startswith(("http://", "https://", "mailto:")):
                continue
            if target.startswith("#"):
                if target[1:] not in anchors:
                    broken.append(f"{markdown}:{number}: no heading has the anchor {target}")
                continue
            path, _, fragment = target.partition("#")
            if not (base / path).exists():
                broken.append(f"{markdown}:{number}: {path} does not exist")
            elif fragment and path.endswith(".md") and fragment not in anchors_of(base / path):
                broken.append(f"{markdown}:{number}: {path} has no heading with the anchor #{fragment}")
    return broken, checked


def main():
    root = pathlib.Path(__file__).resolve().parent.parent
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", type=pathlib.Path)
    args = parser.parse_args()
    files = args.files or [root / "README.md", *sorted((root / "docs").glob("*.md"))]
    broken, checked = [], 0
    for markdown in files:
        file_broken, file_checked = broken_links(markdown)
        broken += file_broken
        checked += file_checked
    for line in broken:
        print(line)
    print(f"check_readme_links: {checked} link(s) in {len(files)} file(s) checked: {'FAIL' if broken else 'PASS'}")
    return 1 if broken else 0

if __name__ == "__main__":
    sys.exit(main())
