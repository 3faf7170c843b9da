#!/usr/bin/env python3
"""Checks that every image in README.md is what its stated command makes today.

  tools/check_readme_images.py --throng BUILD/throng --image-compare BUILD/image_compare [--readme README.md]

Each image line `![...](docs/NAME.png)` must be followed (within a few lines) by an HTML
comment `<!-- command: ... -->` holding the exact command that made it, with the image's
path as its output. The command is run with the output redirected to a scratch file
(`throng` and `tools/...` resolved to this build and checkout), and the result is compared
with the committed image at the golden-image tolerance (per-channel 2, at most 0.1% of
pixels). Prints one line per image and a closing PASS or FAIL.
"""
import argparse
import os
import pathlib
import re
import shlex
import subprocess
import sys
import tempfile

IMAGE = re.compile(r"!\[[^\]]*\]\((docs/[^)]+\.png)\)")
COMMAND = re.compile(r"<!--\s*command:\s*(.*?)\s*-->", re.S)
LOOKAHEAD_LINES = 12


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--throng", required=True)
    parser.add_argument("--image-compare", required=True)
    root = pathlib.Path(__file__).resolve().parent.parent
    parser.add_argument("--readme", default=root / "README.md", type=pathlib.Path)
    args = parser.parse_args()
    lines = args.readme.read_text().splitlines()
    failures, checked = [], 0
    with tempfile.TemporaryDirectory() as scratch:
        for number, line in enumerate(lines):
            match = IMAGE.search(line)
            if not match:
                continue
            image = match.group(1)
            following = "\n".join(lines[number + 1:number + 1 + LOOKAHEAD_LINES])
            found = COMMAND.search(following)
            if not found:
                failures.append(f"{image}: no '<!-- command: ... -->' after it in README.md:{number + 1}")
                continue
            words = shlex.split(found.group(1).replace("\n", " "))
            env = dict(os.environ, THRONG=str(pathlib.Path(args.throng).resolve()))  # for tools/ scripts that run throng
            while words and re.fullmatch(r"[A-Z_]+=.*", words[0]):  # leading VAR=value settings
                key, value = words.pop(0).split("=", 1)
                env[key] = value
            if image not in words:
                failures.append(f"{image}: its command does not write it")
                continue
            result = str(pathlib.Path(scratch) / pathlib.Path(image).name)
            words = [result if w == image else w for w in words]
            if words[0] in ("throng", "build/release/throng"):
                words[0] = args.throng
            elif words[0].startswith("tools/"):
                words[0] = str(root / words[0])
            run = subprocess.run(words, cwd=root, env=env, capture_output=True, text=True)
            if run.returncode != 0:
                failures.append(f"{image}: its command failed ({run.returncode}): {run.stderr.strip()}")
                continue
            compare = subprocess.run([args.image_compare, result, str(root / image), "--tolerance", "2", "--max-fraction", "0.001"],
                                     capture_output=True, text=True)
            checked += 1
            print(f"{image}: {compare.stdout.strip().splitlines()[-1] if compare.stdout.strip() else 'compared'}")
            if compare.returncode != 0:
                failures.append(f"{image}: differs from what its command makes today")
    for failure in failures:
        print(failure)
    print(f"check_readme_images: {checked} image(s) checked: " + ("FAIL" if failures or checked == 0 else "PASS"))
    return 1 if failures or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
