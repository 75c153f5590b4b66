#!/usr/bin/python3
"""Comments that cite the design notes name a file that exists and a section of it.

The notes live beside the code (support/DESIGN.md, models/DESIGN.md, sim/DESIGN.md,
renders/DESIGN.md, scenes/DESIGN.md). A citation is `<folder>/DESIGN.md`,
optionally followed by "<section title>" (its start is enough, and it may
run over comment lines). Prints "file:line: ..." for a citation of a file
or a section that does not exist, or a bare DESIGN / DESIGN.md; exits 1 then.

usage: check_design_notes.py ROOT [FOLDER ...] [--skip=FOLDER ...]   (folders to scan; default below)
"""
import os
import re
import sys

FOLDERS = ["support", "models", "geometry", "sim", "renders", "scenes", "tests", "python"]
SOURCES = (".h", ".hpp", ".cpp", ".cc", ".py", ".cmake", ".txt")
CITATION = re.compile(r'([A-Za-z_]+)/DESIGN\.md(\s*[("]*\s*"([^"]+)")?')
BARE = re.compile(r'(?<![/\w])DESIGN(\.md)?\b')
# A line break inside a comment: newline, indentation and the comment marker.
COMMENT_BREAK = re.compile(r'\s*\n\s*(?://+|#)\s*')


def headings(path):
    with open(path, encoding="utf-8") as f:
        return [line[3:].strip() for line in f if line.startswith("## ")]


def main(argv):
    root = argv[1]
    folders = [a for a in argv[2:] if not a.startswith("--skip=")] or FOLDERS
    skip = {a[len("--skip="):].rstrip("/") for a in argv[2:] if a.startswith("--skip=")}
    findings = []
    for top in folders:
        for folder, dirs, files in os.walk(os.path.join(root, top)):
            dirs[:] = sorted(d for d in dirs if not d.startswith((".", "build"))
                             and os.path.relpath(os.path.join(folder, d), root) not in skip)
            for name in sorted(files):
                if not name.endswith(SOURCES) or name == "DESIGN.md":
                    continue
                path = os.path.join(folder, name)
                rel = os.path.relpath(path, root)
                text = open(path, encoding="utf-8", errors="replace").read()
                joined = COMMENT_BREAK.sub(" ", text)
                # The k-th match in `joined` is the k-th in `text` (a joined line
                # break touches no citation): its line is the original's.
                citation_lines = [text.count("\n", 0, m.start()) + 1 for m in re.finditer(r"/DESIGN\.md", text)]
                bare_lines = [text.count("\n", 0, m.start()) + 1 for m in BARE.finditer(text)]

                for k, match in enumerate(CITATION.finditer(joined)):
                    line = citation_lines[k]
                    notes = os.path.join(root, match.group(1), "DESIGN.md")
                    if not os.path.isfile(notes):
                        findings.append(f"{rel}:{line}: cites {match.group(1)}/DESIGN.md, "
                                        "which does not exist")
                        continue
                    title = match.group(3)
                    if title is not None:
                        title = " ".join(title.split())
                        if not any(h.startswith(title) for h in headings(notes)):
                            findings.append(f"{rel}:{line}: cites \"{title}\", not a section "
                                            f"of {match.group(1)}/DESIGN.md")
                for k, match in enumerate(BARE.finditer(joined)):
                    findings.append(f"{rel}:{bare_lines[k]}: cites {match.group(0)} without its folder "
                                    "(models/, sim/, renders/ or scenes/DESIGN.md)")
    for finding in findings:
        print(finding)
    if findings:
        return 1
    print("check_design_notes: every citation names a design note and a section that exist")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
