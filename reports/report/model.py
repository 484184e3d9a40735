"""The section model of the report, and its two renderings.

Every table, figure and paragraph is built once, as data; render_markdown and render_html
turn the same list of sections into report.md and index.html, so the two cannot drift.
"""
import html
import os
from dataclasses import dataclass, field


@dataclass
class Text:
    """A paragraph (Markdown inline code in backquotes is kept; HTML shows it as code)."""
    text: str


@dataclass
class Link:
    """A table cell that links in index.html (its text alone in report.md). `attributes` is
    extra HTML of the anchor, already escaped (the viewer's data-view)."""
    text: str
    href: str
    attributes: str = ""

    def __str__(self):
        return self.text


@dataclass
class Tally:
    """A table cell of run counts, agree / classified / failure: plain in report.md, each count
    coloured in index.html (report.css), a failure count that is not zero marked."""
    agree: int
    classified: int
    failure: int

    def __str__(self):
        return f"{self.agree} / {self.classified} / {self.failure}"


@dataclass
class Table:
    header: list
    rows: list


@dataclass
class Figure:
    path: str  # relative to the report folder, e.g. "figures/timing.png"
    alt: str


@dataclass
class Interactive:
    """A part of the page that only a browser shows (the 3D viewer, a collapsed long list):
    `html` verbatim in index.html, `markdown` (a sentence pointing to it) in report.md."""
    html: str
    markdown: str = ""


@dataclass
class Section:
    title: str
    blocks: list = field(default_factory=list)

    def add(self, *blocks):
        self.blocks.extend(b for b in blocks if b is not None)
        return self


def md_cell(value):
    """A Markdown table cell that never breaks its row: pipes escaped, line breaks joined."""
    return str(value).replace("\\", "\\\\").replace("|", "\\|").replace("\r", " ").replace("\n", " ")


def md_table(table):
    lines = ["| " + " | ".join(md_cell(h) for h in table.header) + " |", "|" + "---|" * len(table.header)]
    lines += ["| " + " | ".join(md_cell(v) for v in row) + " |" for row in table.rows]
    return lines


def render_markdown(title, intro, sections):
    """report.md: a title, intro paragraphs, then each section with its blocks."""
    out = [f"# {title}", ""]
    for line in intro:
        out += [line]
    out.append("")
    for s in sections:
        out += [f"## {s.title}", ""]
        for b in s.blocks:
            if isinstance(b, Text):
                out += [b.text, ""]
            elif isinstance(b, Table):
                out += md_table(b) + [""]
            elif isinstance(b, Figure):
                out += [f"![{b.alt}]({b.path})", ""]
            elif isinstance(b, Interactive) and b.markdown:
                out += [b.markdown, ""]
    return "\n".join(out).rstrip("\n") + "\n"


def _inline_html(text):
    """Escapes text and shows `code` spans as <code>."""
    parts = html.escape(text).split("`")
    return "".join(f"<code>{p}</code>" if i % 2 else p for i, p in enumerate(parts))


def html_cell(value):
    """A cell's HTML: escaped text, a Link as an anchor, a Tally's counts each in its class."""
    if isinstance(value, Link):
        return f"<a href='{html.escape(value.href)}'{value.attributes}>{html.escape(value.text)}</a>"
    if isinstance(value, Tally):
        failure = "failure" + (" nonzero" if value.failure else "")
        return (f"<span class='agree'>{value.agree}</span> / <span class='classified'>{value.classified}</span>"
                f" / <span class='{failure}'>{value.failure}</span>")
    return html.escape(str(value))


def html_row(row):
    """A table row; a row holding a Tally with failures is marked too."""
    failing = any(isinstance(v, Tally) and v.failure for v in row)
    return (f"<tr class='failing'>" if failing else "<tr>") + "".join(f"<td>{html_cell(v)}</td>" for v in row) + "</tr>"


def html_table(table):
    out = ["<table><tr>" + "".join(f"<th>{html.escape(str(h))}</th>" for h in table.header) + "</tr>"]
    out += [html_row(row) for row in table.rows]
    return "\n".join(out + ["</table>"])


# The page's own stylesheet (no network): report.css beside this file, inlined into index.html
# so that the page opens from disk alone.
with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "report.css")) as _css:
    STYLE = _css.read()


def render_html(title, intro, sections):
    """index.html: the same sections as report.md, for a browser."""
    body = [f"<h1>{html.escape(title)}</h1>"] + [f"<p>{_inline_html(line.lstrip('- '))}</p>" for line in intro]
    for s in sections:
        body.append(f"<h2>{html.escape(s.title)}</h2>")
        for b in s.blocks:
            if isinstance(b, Text):
                body.append(f"<p>{_inline_html(b.text)}</p>")
            elif isinstance(b, Table):
                body.append(html_table(b))
            elif isinstance(b, Figure):
                body.append(f"<img src='{html.escape(b.path)}' alt='{html.escape(b.alt)}'>")
            elif isinstance(b, Interactive):
                body.append(b.html)
    return (f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{html.escape(title)}</title>"
            f"<style>{STYLE}</style></head><body>\n" + "\n".join(body) + "\n</body></html>\n")
