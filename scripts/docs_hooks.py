"""MkDocs hooks for railjoint's manual (mkdocs.yml: hooks).

The pages live in docs/ but show the repository's own figures and files
(scenes/validation/figures/fig4_5.png, scenes/report/outputs.md): written as
`../scenes/...` so that they also open on a forge, they are taken into the
site here, and a link to a file that is not there fails `mkdocs build
--strict`. The Python API page is made from the built module's docstrings
(RAILJOINT_PYTHONPATH, default build/python), so it cannot drift from them,
and the home page is the README, its links taken from the top to docs/.
"""
import importlib
import logging
import inspect
import os
import re
import sys
import tempfile

from mkdocs.structure.files import File

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # scripts/..
REPO_LINK = re.compile(r"\]\(\.\./([^)#\s]+)")
API_PAGE = "python-api.md"
HOME_PAGE = "index.md"
README_LINK = re.compile(r"\]\((?!https?:|mailto:|#)([^)\s]+)\)")
LOG = logging.getLogger("mkdocs.hooks.railjoint")  # a warning fails --strict


def _repo_targets(docs_dir):
    targets = set(REPO_LINK.findall(_home_markdown()))
    for name in sorted(os.listdir(docs_dir)):
        if name.endswith(".md"):
            with open(os.path.join(docs_dir, name), encoding="utf-8") as page:
                targets.update(REPO_LINK.findall(page.read()))
    return targets


def _api_markdown():
    path = os.environ.get("RAILJOINT_PYTHONPATH", os.path.join(ROOT, "build", "python"))
    sys.path.insert(0, path)
    try:
        module = importlib.import_module("railjoint")
    except ImportError as error:
        raise SystemExit(f"docs: the Python API page needs the built module (RAILJOINT_PYTHONPATH={path}): {error}")
    out = ["# Python API", "",
           "Made from the docstrings of the built module `railjoint` when the manual is built "
           "(`scripts/docs_hooks.py`); see [From Python](python.md) for the guide.", ""]
    names = getattr(module, "__all__", None) or [n for n in dir(module) if not n.startswith("_")]
    functions = [n for n in names if inspect.isroutine(getattr(module, n))]
    classes = [n for n in names if inspect.isclass(getattr(module, n))]
    out += ["## Functions", ""]
    for name in functions:
        out += [f"### `{name}`", "", "```text", inspect.getdoc(getattr(module, name)) or "(no docstring)", "```", ""]
    out += ["## Classes", ""]
    for name in classes:
        cls = getattr(module, name)
        out += [f"### `{name}`", "", "```text", inspect.getdoc(cls) or "(no docstring)", "```", ""]
        members = []
        for member, value in sorted(vars(cls).items()):
            if member.startswith("_"):
                continue
            doc = inspect.getdoc(value) or ""
            members.append(f"| `{member}` | {' '.join(doc.split()) or '(no docstring)'} |")
        if members:
            out += ["| member | what |", "|---|---|"] + [m.replace("\n", " ") for m in members] + [""]
    return "\n".join(out) + "\n"


def _home_markdown():
    with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as readme:
        text = readme.read()
    # README's docs/x.md is the site's x.md; its other files are the repository's.
    return README_LINK.sub(lambda m: "](" + (m.group(1)[5:] if m.group(1).startswith("docs/") else "../" + m.group(1)) + ")",
                           text)


def on_files(files, config):
    for target in sorted(_repo_targets(config["docs_dir"])):
        if not os.path.isfile(os.path.join(ROOT, target)):
            LOG.warning("a page links to ../%s, which is not in the repository", target)
        elif files.get_file_from_path(target) is None:
            files.append(File(target, ROOT, config["site_dir"], config["use_directory_urls"]))
    folder = tempfile.mkdtemp(prefix="railjoint-docs-")
    for name, text in ((API_PAGE, _api_markdown()), (HOME_PAGE, _home_markdown())):
        with open(os.path.join(folder, name), "w", encoding="utf-8") as page:
            page.write(text)
        files.append(File(name, folder, config["site_dir"], config["use_directory_urls"]))
    return files


def on_page_markdown(markdown, page, config, files):
    # A repository file is at the site's top, as on_files put it.
    depth = page.file.src_uri.count("/")
    return REPO_LINK.sub("](" + "../" * depth, markdown)
