#!/usr/bin/python3
"""Module-internal headers stay internal (STYLE.md 15, scenes/CMakeLists.txt).

Each module folder lists the headers other modules may include
(railjoint_module() in its CMakeLists.txt; CMake writes them into MODULES,
one line per folder: "<folder> <header> <header> ..."). Every other header
of the folder is internal: only the folder's own files and its tests
(tests/<name>/ for the module <name> or scenes/<name>) may include it.
A public header may include only public headers of its own module, or the
internal one would reach every caller through it. And the modules' includes
(tests aside) form no cycle: no report includes a study, and so on. A module
marked --ground-floor (railjoint_module(... GROUND_FLOOR ...): support/)
includes no other module at all: it is below everything.

Prints one line per finding, "file:line: ..." (paths relative to ROOT), and
exits 1 when there is any.

usage: check_includes.py MODULES ROOT [SKIP ...]   (SKIP: folders under ROOT not scanned)
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
SOURCES = (".h", ".hpp", ".cpp", ".cc")


GROUND_FLOOR = "--ground-floor"


def read_modules(path):
    """{folder: its public headers} and the set of ground-floor folders."""
    modules, ground = {}, set()
    with open(path, encoding="utf-8") as f:
        for line in f:
            words = line.split()
            if words:
                folder = words[0].rstrip("/")
                if GROUND_FLOOR in words[1:]:
                    ground.add(folder)
                modules[folder] = set(w for w in words[1:] if w != GROUND_FLOOR)
    return modules, ground


def module_of(path, modules):
    """The module folder holding `path` (the longest folder that is a prefix), or None."""
    best = None
    for folder in modules:
        if path.startswith(folder + "/") and (best is None or len(folder) > len(best)):
            best = folder
    return best


def owner_of(path, modules):
    """Who a file belongs to: its module, or the module its tests/<name>/ folder tests."""
    if path.startswith("tests/"):
        parts = path.split("/")
        if len(parts) > 2:
            for folder in (parts[1], "scenes/" + parts[1]):
                if folder in modules:
                    return folder
        return None
    return module_of(path, modules)


def sources(root, skip):
    for folder, dirs, files in os.walk(root):
        rel = os.path.relpath(folder, root)
        rel = "" if rel == "." else rel + "/"
        dirs[:] = sorted(d for d in dirs
                         if not d.startswith(".") and not d.startswith("build")
                         and (rel + d) not in skip
                         and not os.path.exists(os.path.join(folder, d, "CMakeCache.txt")))
        for name in sorted(files):
            if name.endswith(SOURCES):
                yield rel + name


def cycles(uses):
    """A finding for each module that reaches itself through others' includes (the first one found)."""
    found = []
    state = {}  # module -> 1 on the current path, 2 done

    def visit(module, path):
        state[module] = 1
        for target in sorted(uses[module]):
            if state.get(target) == 1:
                loop = path[path.index(target):] + [target]
                where = ", ".join(uses[a][b] for a, b in zip(loop, loop[1:]))
                found.append(f"{uses[module][target]}: closes a cycle of modules {' -> '.join(loop)} ({where})")
            elif target not in state:
                visit(target, path + [target])
        state[module] = 2

    for module in sorted(uses):
        if module not in state:
            visit(module, [module])
    return found


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    modules, ground = read_modules(argv[1])
    root = argv[2]
    skip = {s.rstrip("/") for s in argv[3:]}
    findings = []
    uses = {folder: {} for folder in modules}  # module -> {module it includes: first file:line}
    for folder, public in sorted(modules.items()):
        for header in sorted(public):
            if not os.path.isfile(os.path.join(root, folder, header)):
                findings.append(f"{folder}/CMakeLists.txt: public header {folder}/{header} does not exist")
    for path in sources(root, skip):
        owner = owner_of(path, modules)
        own_module = module_of(path, modules)
        is_public_header = own_module is not None and path[len(own_module) + 1:] in modules[own_module]
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                match = INCLUDE.match(line)
                if not match:
                    continue
                included = match.group(1)
                target = module_of(included, modules)
                if target is not None and own_module is not None and target != own_module:
                    uses[own_module].setdefault(target, f"{path}:{number}")
                    if own_module in ground:
                        findings.append(f"{path}:{number}: includes {included} of {target}/, but {own_module}/ "
                                        f"is the ground floor: it includes no other module")
                if target is None or included[len(target) + 1:] in modules[target]:
                    continue
                if target != owner:
                    findings.append(f"{path}:{number}: includes {included}, internal to {target}/ "
                                    f"(its public headers: railjoint_module() in its CMakeLists.txt)")
                elif is_public_header:
                    findings.append(f"{path}:{number}: public header includes {included}, internal to "
                                    f"{target}/: make it public too, or include it in a .cpp")
    findings += cycles(uses)
    for finding in findings:
        print(finding)
    if findings:
        print(f"check_includes: {len(findings)} finding(s)", file=sys.stderr)
        return 1
    print(f"check_includes: {len(modules)} modules, every include goes through a public header")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
