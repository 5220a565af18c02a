#!/usr/bin/env python3
"""Fails (exit 1) when a source file includes a project header its module may not use.

The allowed edges are tools/module_graph.txt, the graph docs/architecture.md describes. Each
back-edge is printed as one line: FILE:LINE includes HEADER: MODULE may not include TARGET.
"""
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/[^"]+"')


def read_graph():
    graph = {}
    for line in (ROOT / "tools" / "module_graph.txt").read_text().splitlines():
        line = line.split("#", 1)[0].split()
        if line:
            graph[line[0]] = set(line[1:])
    return graph


def module_of(path, graph):
    best = None
    for module in graph:
        if path == module or path.startswith(module + "/"):
            if best is None or len(module) > len(best):
                best = module
    return best


def main():
    graph = read_graph()
    top_level = {m.split("/")[0] for m in graph}
    files = subprocess.run(["git", "ls-files", "*.cpp", "*.h", "*.hpp"], cwd=ROOT,
                           capture_output=True, text=True, check=True).stdout.split()
    problems = []
    for name in files:
        module = module_of(name, graph)
        if module is None:
            problems.append(f"{name}: in no module of tools/module_graph.txt")
            continue
        for number, line in enumerate((ROOT / name).read_text(errors="replace").splitlines(), 1):
            match = INCLUDE.match(line)
            if match and match.group(1) in top_level and match.group(1) not in graph[module]:
                problems.append(f"{name}:{number} includes {line.split(chr(34))[1]}: "
                                f"{module} may not include {match.group(1)}")
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems:
        print(f"module graph: {len(problems)} back-edge(s); see tools/module_graph.txt and "
              "docs/architecture.md", file=sys.stderr)
        return 1
    print(f"module graph: {len(files)} files, no back-edge")
    return 0


if __name__ == "__main__":
    sys.exit(main())
