"""The HTML and figure helpers of the design reports (:mod:`seacable.report`, :mod:`seacable.report_cable`): number
formatting, escaping, tables, the page's CSS and inline PNG figures. Nothing here reads a result."""

from __future__ import annotations

import base64
import html
import io
import math
import os
import re
from pathlib import Path

import pandas as pd


def _num(value, sig: int = 4, scale: float = 1.0) -> str:
    """One number alone (not in a table column): ``sig`` significant digits, scientific below 1e-3 and from 1e7."""
    return _column([value], scale=scale, sig=sig)[0]


def _scientific(x: float, sig: int) -> str:
    m, e = f"{x:.{sig - 1}e}".split("e")
    return f"{m.replace('-', '&minus;')}&times;10<sup>{int(e)}</sup>"


def _column(values, scale: float = 1.0, sig: int = 4, like=None) -> list[str]:
    """The numbers of one table column in one format: fixed decimals, those that give the largest magnitude
    ``sig`` significant digits, when every other nonzero value still shows one; else all scientific with
    ``sig`` significant digits. None or NaN is a dash, 0 is "0" (and "0.00" in a column of two decimals).
    ``like``: more values [SI] the format is chosen over too (columns of one quantity shown alike)."""
    def scaled(vs):
        return [math.nan if v is None or (isinstance(v, float) and math.isnan(v)) else float(v) / scale for v in vs]

    xs = scaled(values)
    finite = [abs(x) for x in xs + scaled(like if like is not None else []) if math.isfinite(x) and x != 0.0]
    if finite:
        hi, lo = max(finite), min(finite)
        decimals = max(sig - 1 - math.floor(math.log10(hi)), 0)
        fixed = hi < 1e7 and lo >= 10.0 ** -decimals and decimals <= 6
    else:
        decimals, fixed = 0, True
    out = []
    for x in xs:
        if math.isnan(x):
            out.append("&ndash;")
        elif math.isinf(x):
            out.append("&infin;" if x > 0 else "&minus;&infin;")
        elif fixed:
            out.append(f"{x:.{decimals}f}".replace("-", "&minus;"))
        elif x == 0:
            out.append("0")
        else:
            out.append(_scientific(x, sig))
    return out


def _columns(table: pd.DataFrame, spec: dict[str, tuple[float, int]], alike: tuple[str, ...] = ()) -> dict[str, list[str]]:
    """The formatted columns of a table: column -> (scale, significant digits); the columns ``alike`` (one
    quantity: a demand, its capacity and margin) in one format chosen over all of them."""
    pool = [v for c in alike for v in table[c]]
    return {c: _column(list(table[c]), scale, sig, pool if c in alike else None) for c, (scale, sig) in spec.items()}


def _e(text) -> str:
    return html.escape(str(text))


_ABSOLUTE = re.compile(r"(?<![\w.~/:])(/(?:[^\s'\"<>|,;()\[\]{}]+/)+[^\s'\"<>|,;()\[\]{}]*)")


def _status(row) -> tuple[str, str]:
    """A check row's status badge (HTML) and its row class: PASS, FAIL, or the reason it was not checked."""
    passed = row["passed"]
    if passed is None or (isinstance(passed, float) and math.isnan(passed)):
        return f'<span class="skip">{_e(row["status"])}</span>', "skipped"
    if bool(passed):
        return '<span class="pass">PASS</span>', "passed"
    return '<span class="fail">FAIL</span>', "failed"


def _relative(text, base: Path | None) -> str:
    """``text`` with each absolute path in it shown relative to ``base`` (the report's folder), or by its file name
    alone where the two share no folder but the root (or a drive): a report shows no absolute path of the
    machine it was made on."""
    def one(m):
        path = m.group(1)
        try:
            common = os.path.commonpath([path, str(base)]) if base is not None else ""
        except ValueError:  # another drive
            common = ""
        if not common or Path(common) == Path(common).parent:  # only the root in common
            return Path(path).name
        return os.path.relpath(path, base)

    return _ABSOLUTE.sub(one, str(text))


#: The colour of the data in the figures (Okabe & Ito's blue), apart from the page's own blue.
_SERIES = "#0072b2"


#: The resolution of the figures on the page. [dots per inch]
_DPI = 110


def _png(fig) -> str:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=_DPI, bbox_inches="tight", facecolor="white")
    return base64.b64encode(buf.getvalue()).decode("ascii")


def _pyplot():
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    plt.rcParams.update({"font.size": 9, "axes.titlesize": 10, "axes.labelsize": 9, "axes.spines.top": False,
                         "axes.spines.right": False, "axes.grid": True, "grid.color": "#dddddd",
                         "grid.linewidth": 0.6, "font.family": "DejaVu Sans"})
    return plt


def _plain(x) -> str:
    text = re.sub(r"<sup>(.*?)</sup>", r"^\1", _num(float(x)))
    return html.unescape(text).replace("\u2212", "-")


def _table(headers: list[str], rows: list[list[str]], classes: list[str] | None = None, cls: str = "",
           single: bool = False) -> str:
    """An HTML table; ``single``: the first column (the load case, or a system's condition) is the same in every row
    and left out."""
    if single and headers and headers[0] in ("Load case", "Condition"):
        headers, rows = headers[1:], [r[1:] for r in rows]
        cls = f"{cls} single".strip()
    head = "".join(f"<th>{h}</th>" for h in headers)
    body = []
    for k, row in enumerate(rows):
        rc = f' class="{classes[k]}"' if classes and classes[k] else ""
        body.append(f"<tr{rc}>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>")
    return (f'<table class="{cls}"><thead><tr>{head}</tr></thead><tbody>{"".join(body)}</tbody></table>')


def _notes_block(notes: dict[str, str]) -> str:
    if not notes:
        return ""
    items = "".join(f"<li><sup>{k}</sup> {_e(v)}</li>" for v, k in notes.items())
    return f'<ol class="notes">{items}</ol>'


def _mark(notes: dict[str, str], text: str) -> str:
    if not text:
        return ""
    if text not in notes:
        notes[text] = chr(ord("a") + len(notes)) if len(notes) < 26 else str(len(notes) + 1)
    return f"<sup>{notes[text]}</sup>"


_CSS = """
:root { --ink: #1d2733; --muted: #5b6673; --rule: #d5dbe1; --head: #eef2f6; --accent: #1f4e79; }
* { box-sizing: border-box; }
body { margin: 0; background: #ffffff; color: var(--ink);
       font: 14px/1.5 "Segoe UI", "Helvetica Neue", Helvetica, Arial, "DejaVu Sans", sans-serif; }
main { max-width: 1180px; margin: 0 auto; padding: 32px 40px 64px; }
header.top { border-bottom: 3px solid var(--accent); padding-bottom: 12px; margin-bottom: 24px; }
header.top h1 { margin: 0 0 4px; font-size: 26px; font-weight: 600; color: var(--accent); }
header.top .meta { color: var(--muted); font-size: 13px; }
h2 { font-size: 19px; font-weight: 600; margin: 36px 0 10px; padding-bottom: 4px; border-bottom: 1px solid var(--rule);
     color: var(--accent); }
h3 { font-size: 15px; font-weight: 600; margin: 20px 0 8px; }
p { margin: 6px 0 10px; }
.verdict { display: flex; flex-wrap: wrap; gap: 12px; margin: 8px 0 4px; }
.card { flex: 1 1 200px; border: 1px solid var(--rule); border-radius: 6px; padding: 10px 14px; background: #fafbfc; }
.card .k { color: var(--muted); font-size: 12px; text-transform: uppercase; letter-spacing: .04em; }
.card .v { font-size: 20px; font-weight: 600; margin-top: 2px; }
.card.ok .v { color: #2e7d32; } .card.bad .v { color: #c62828; } .card.warn .v { color: #8a6d00; }
table { border-collapse: collapse; margin: 6px 0 8px; font-size: 12.5px; width: 100%; }
th { background: var(--head); text-align: left; font-weight: 600; padding: 6px 8px; border-bottom: 2px solid var(--rule);
     vertical-align: bottom; }
td { padding: 4px 8px; border-bottom: 1px solid #e8ecf0; vertical-align: top; }
tbody tr:nth-child(even) td { background: #f8fafb; }
table.num td { font-variant-numeric: tabular-nums; white-space: nowrap; }
table.num td:nth-child(n+4) { text-align: right; }
table.num.single td:nth-child(n+3) { text-align: right; }
table.num:not(.single) td:first-child { white-space: normal; min-width: 120px; }
table.num.checks td:last-child, table.num.extremes td:last-child { text-align: left; white-space: normal; }
table.kv { width: auto; min-width: 480px; } table.kv th { width: 240px; background: none; font-weight: 600;
     border-bottom: 1px solid #e8ecf0; padding: 4px 8px; vertical-align: top; }
table.kv tbody tr:nth-child(even) td { background: none; }
table.basis td:nth-child(2) { white-space: nowrap; }
tr.failed td { background: #fdecea !important; }
span.pass { color: #1b5e20; background: #e3f1e4; padding: 1px 8px; border-radius: 10px; font-weight: 600; }
span.fail { color: #ffffff; background: #c62828; padding: 1px 8px; border-radius: 10px; font-weight: 600; }
span.skip { color: var(--muted); font-style: italic; }
ol.notes { font-size: 12px; color: var(--muted); margin: 2px 0 12px; padding-left: 18px; list-style: none; }
ol.notes li sup { font-weight: 600; margin-right: 4px; }
figure { margin: 14px 0 20px; } figure img { max-width: 100%; height: auto; border: 1px solid #eef0f2; }
figcaption { color: var(--muted); font-size: 12.5px; margin-top: 4px; }
details { margin: 8px 0; border: 1px solid var(--rule); border-radius: 6px; padding: 6px 12px; background: #fafbfc; }
details summary { cursor: pointer; font-weight: 600; }
pre { font: 12px/1.45 "DejaVu Sans Mono", Menlo, Consolas, monospace; white-space: pre-wrap; margin: 8px 0; }
code { font: 12px "DejaVu Sans Mono", Menlo, Consolas, monospace; }
.method { color: var(--muted); font-size: 12.5px; }
footer { margin-top: 48px; color: var(--muted); font-size: 12px; border-top: 1px solid var(--rule); padding-top: 8px; }
@media print { main { padding: 0; } h2 { break-after: avoid; } figure, table { break-inside: avoid; } }
"""


def _figure(fig) -> str:
    if fig is None:
        return ""
    img, caption = fig
    return (f'<figure><img alt="{_e(caption)}" src="data:image/png;base64,{img}">'
            f"<figcaption>{_e(caption)}</figcaption></figure>")


def _kv(pairs: list[tuple[str, str]]) -> str:
    return '<table class="kv"><tbody>' + "".join(f"<tr><th>{k}</th><td>{v}</td></tr>" for k, v in pairs) + \
        "</tbody></table>"
