#!/usr/bin/env python3
"""Checks the module rules of DESIGN.md §2 and the size limits, on the source tree.

  tools/check_structure.py [--root DIR]

Rules (each violation is printed; exit 1 if any):
  1. A module includes only its own headers and those of the modules it may depend on.
  2. A module links (in its CMakeLists.txt) every module whose headers it includes.
  3. Only engine/viewer includes GLFW or Dear ImGui.
  4. No engine source file is longer than 400 lines.
  5. No function body in engine/ is longer than 80 lines.
  6. shaders/: the palette index arithmetic (firstPose + frame * jointCount) is written once.
  7. Rules 4 and 5 also hold in tests/quality, the measurement library and report that
     tests and tools share (it is not a module, so rules 1-3 don't apply).
It also prints the longest function and the largest file, so the limits can be watched.
"""
import argparse
import pathlib
import re
import sys

# Allowed dependencies, from DESIGN.md §2 (each module may also use itself).
ALLOWED = {
    "core": set(),
    "motion": {"core"},
    "crowd": {"motion", "core"},
    "gpu": {"core"},
    "render": {"gpu", "crowd", "motion", "core"},
    "viewer": {"render", "gpu", "crowd", "motion", "core"},
    "app": {"viewer", "render", "gpu", "crowd", "motion", "core"},
}
MAX_FILE_LINES = 400
MAX_FUNCTION_LINES = 80
SOURCE_SUFFIXES = {".h", ".cpp"}
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]throng/(\w+)/')
WINDOWING = re.compile(r'^\s*#\s*include\s*[<"](GLFW/|imgui|backends/imgui)')
LINKED = re.compile(r"throng::(\w+)")


HEX_DIGITS = "0123456789abcdefABCDEF"


def strip_code(text):
    """Blanks comments, string and character literals (keeping newlines) so braces can be counted."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + (m.group(1) if m else "") + '"', i)
            end = n if end < 0 else end + len(m.group(1) if m else "") + 2
            out.append('""' + "\n" * text.count("\n", i, end))
            i = end
        elif c == "'" and i > 0 and text[i - 1] in HEX_DIGITS and i + 1 < n and text[i + 1] in HEX_DIGITS:
            out.append(c)  # a digit separator (10'000), not a character literal
            i += 1
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def function_lengths(path):
    """(first line, lines) of every function body at namespace or class scope, by brace matching."""
    # Preprocessor lines are not statements: a macro's parentheses would make the next brace look
    # like a function's.
    # Continued lines (a trailing backslash) belong to the directive; newlines are kept, so
    # line numbers stay right.
    code = re.sub(r"(?m)^[ \t]*#(?:.*\\\n)*.*$", lambda m: "\n" * m.group(0).count("\n"), strip_code(path.read_text()))
    scopes = []  # per open brace: is it a function body, and where it started
    results, statement_start, line = [], 0, 1
    for index, c in enumerate(code):
        if c == "\n":
            line += 1
        elif c == "{":
            head = code[statement_start:index]
            in_function = any(kind for kind, _ in scopes)
            is_function = (not in_function and ")" in head and not re.search(r"\b(class|struct|enum|union|namespace)\b", head.split("(")[0])
                           and not re.search(r"=\s*$", head.strip()) and not head.rstrip().endswith(("=", ",")))
            scopes.append((is_function, line))
            statement_start = index + 1
        elif c == "}":
            if scopes:
                is_function, start = scopes.pop()
                if is_function:
                    results.append((start, line - start + 1))
            statement_start = index + 1
        elif c == ";":
            statement_start = index + 1
    return results


def module_of(path, engine):
    return path.relative_to(engine).parts[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=pathlib.Path(__file__).resolve().parent.parent, type=pathlib.Path)
    args = parser.parse_args()
    engine = args.root / "engine"
    problems = []
    longest_function = (0, "")
    largest_file = (0, "")
    used = {module: set() for module in ALLOWED}
    for path in sorted(engine.rglob("*")):
        if path.suffix not in SOURCE_SUFFIXES:
            continue
        module = module_of(path, engine)
        relative = path.relative_to(args.root)
        lines = path.read_text().splitlines()
        largest_file = max(largest_file, (len(lines), str(relative)))
        if len(lines) > MAX_FILE_LINES:
            problems.append(f"{relative}: {len(lines)} lines, over {MAX_FILE_LINES}")
        for number, text in enumerate(lines, 1):
            if WINDOWING.match(text) and module != "viewer":
                problems.append(f"{relative}:{number}: GLFW or Dear ImGui outside engine/viewer")
            match = INCLUDE.match(text)
            if not match or match.group(1) in ("shaders",):
                continue
            other = match.group(1)
            if other != module:
                used[module].add(other)
                if other not in ALLOWED.get(module, set()):
                    problems.append(f"{relative}:{number}: {module} must not depend on {other}")
        for start, length in function_lengths(path):
            longest_function = max(longest_function, (length, f"{relative}:{start}"))
            if length > MAX_FUNCTION_LINES:
                problems.append(f"{relative}:{start}: function of {length} lines, over {MAX_FUNCTION_LINES}")
    for module, others in used.items():
        cmake = engine / module / "CMakeLists.txt"
        linked = set(LINKED.findall(cmake.read_text())) if cmake.exists() else set()
        for other in sorted(others - linked):
            problems.append(f"{cmake.relative_to(args.root)}: {module} includes {other} but does not link throng::{other}")
    # Shared test code is held to the same size limits as the engine: it is read as often.
    for path in sorted((args.root / "tests" / "quality").rglob("*")):
        if path.suffix not in SOURCE_SUFFIXES:
            continue
        relative = path.relative_to(args.root)
        lines = len(path.read_text().splitlines())
        if lines > MAX_FILE_LINES:
            problems.append(f"{relative}: {lines} lines, over {MAX_FILE_LINES}")
        for start, length in function_lengths(path):
            if length > MAX_FUNCTION_LINES:
                problems.append(f"{relative}:{start}: function of {length} lines, over {MAX_FUNCTION_LINES}")
    shaders = args.root / "shaders"
    index_sites = [f"{p.name}:{n}" for p in sorted(shaders.glob("*")) for n, t in enumerate(p.read_text().splitlines(), 1)
                   if re.search(r"firstPose\s*\+", t)]
    if len(index_sites) > 1:
        problems.append("shaders: palette index arithmetic written more than once: " + ", ".join(index_sites))
    for problem in problems:
        print(problem)
    print(f"longest function: {longest_function[0]} lines at {longest_function[1]}; "
          f"largest file: {largest_file[0]} lines, {largest_file[1]}")
    print("check_structure: " + ("FAIL" if problems else "PASS"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
