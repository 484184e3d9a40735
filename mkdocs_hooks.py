"""MkDocs hooks (mkdocs.yml `hooks:`): the reference pages generated from the program itself at
each build, never copied by hand, so they cannot go stale.

After the pages are built, Doxygen (Doxyfile) writes the C++ API reference from the headers'
`///` comments into the site's api/ folder; without doxygen the build warns.

A page holds a marker where its generated part goes:
  <!-- generated: crossdiv --help-all -->   the help of every command, from the binary
  <!-- generated: python module -->        every function of the Python module, its signature
                                            and docstring
The binary is $CROSSDIV, else build/verification/crossdiv; the module is imported from
$CROSSDIV_PYTHONPATH, else build/python. When either is missing the build warns, which fails a
strict build (the documentation test) with the reason.
"""
import inspect
import logging
import os
import subprocess
import sys

log = logging.getLogger("mkdocs.plugins.crossdiv")
ROOT = os.path.dirname(os.path.abspath(__file__))
HELP_MARKER = "<!-- generated: crossdiv --help-all -->"
PYTHON_MARKER = "<!-- generated: python module -->"


def _help_text():
    binary = os.environ.get("CROSSDIV", os.path.join(ROOT, "build", "verification", "crossdiv"))
    try:
        r = subprocess.run([binary, "--help-all"], capture_output=True, text=True, timeout=60)
    except OSError as e:
        log.warning(f"the command-line reference needs the built program ({binary}): {e}")
        return "(not generated: the program was not built)"
    if r.returncode != 0:
        log.warning(f"{binary} --help-all exited {r.returncode}: {r.stderr.strip()[:200]}")
    return "```\n" + r.stdout.rstrip() + "\n```"


def _python_text():
    path = os.environ.get("CROSSDIV_PYTHONPATH", os.path.join(ROOT, "build", "python"))
    sys.path.insert(0, path)
    try:
        import crossdiv  # noqa: the module built beside the program
    except ImportError as e:
        log.warning(f"the Python reference needs the built module (in {path}): {e}")
        return "(not generated: the module was not built)"
    finally:
        sys.path.remove(path)
    out = [inspect.getdoc(crossdiv) or ""]
    for name in sorted(n for n in dir(crossdiv) if not n.startswith("_")):
        obj = getattr(crossdiv, name)
        doc = inspect.getdoc(obj) or ""
        if inspect.isclass(obj):
            doc = (doc or f"class {name}") + "\n(a class: " + ", ".join(c.__name__ for c in obj.__mro__[1:-1]) + ")"
        out.append(f"## {name}\n\n```\n{doc}\n```")
    return "\n\n".join(out)


def on_page_markdown(markdown, page, config, files):
    if HELP_MARKER in markdown:
        markdown = markdown.replace(HELP_MARKER, _help_text())
    if PYTHON_MARKER in markdown:
        markdown = markdown.replace(PYTHON_MARKER, _python_text())
    return markdown


def on_post_build(config):
    doxyfile = os.path.join(ROOT, "Doxyfile")
    with open(doxyfile) as f:
        settings = f.read() + f"\nOUTPUT_DIRECTORY = {config['site_dir']}\n"
    try:
        r = subprocess.run([os.environ.get("DOXYGEN", "doxygen"), "-"], input=settings, capture_output=True, text=True, cwd=ROOT, timeout=600)
    except OSError as e:
        log.warning(f"the C++ API reference needs doxygen (Debian doxygen): {e}")
        return
    if r.returncode != 0 or not os.path.exists(os.path.join(config["site_dir"], "api", "index.html")):
        log.warning(f"doxygen exited {r.returncode} without api/index.html: {r.stderr.strip()[:300]}")
