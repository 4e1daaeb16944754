"""The rich display of an evaluation in a notebook (``_repr_html_``): the regime in words, the
checks table with each formula in MathML (the library's renderer, pulldown-latex) and the
motion figure as inline SVG (the report's own)."""

from __future__ import annotations

from functools import lru_cache
from html import escape
from typing import TYPE_CHECKING, Any

from . import _native

if TYPE_CHECKING:
    from ._api import Evaluation


@lru_cache(maxsize=None)
def quantities(model: str) -> dict[str, dict[str, str]]:
    """The model's closed forms by JSON key (guide §14): symbol, unit, equation, MathML, LaTeX, meaning."""
    names = ("id", "symbol", "unit", "equation", "symbol_mathml", "mathml", "latex", "words")
    return {row[0]: dict(zip(names, row)) for row in _native.quantities(model)}


@lru_cache(maxsize=None)
def law_words() -> dict[str, str]:
    """The integration regimes of the laws in words, by JSON id (guide §14)."""
    return dict(_native.law_regimes())


def number(value: Any) -> str:
    """A number to six significant figures (the table's; the data keeps every digit)."""
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float):
        return f"{value:.6g}"
    return escape(str(value))


def evaluation_html(e: "Evaluation") -> str:
    """The evaluation as an HTML fragment."""
    table = quantities(e.model)
    words = law_words()
    laws = []
    for law in e.laws:
        summary = e.data[law["summary"]]
        said = (
            "does not exist for these parameters"
            if summary is None
            else escape(words.get(summary["regime"], summary["regime"]))
        )
        laws.append(f"{escape(law['name'])}: {said}")
    rows = []
    for c in e.checks:
        q = table.get(c["quantity"], {})
        mark = "✓" if c["pass"] else "✗"
        rows.append(
            "<tr>"
            f"<td>{q.get('symbol_mathml', escape(c['quantity']))}</td>"
            f"<td>{q.get('mathml', '')}</td>"
            f"<td>{escape(c['equation'])}</td>"
            f"<td>{number(c['closed_form'])}</td>"
            f"<td>{number(c['numeric'])}</td>"
            f"<td>{escape(q.get('unit', ''))}</td>"
            f"<td>{'—' if c['rel_error'] is None else format(c['rel_error'], '.1e')}</td>"
            f"<td>{mark}</td>"
            "</tr>"
        )
    n_pass = sum(c["pass"] for c in e.checks)
    return (
        '<div class="stickslip">'
        f"<p><b>{escape(e.model)}</b>: closed forms in the regime "
        f"<b>{escape(e.regime['words'])}</b> ({escape(e.regime['why'])}); "
        f"exact integration, {'; '.join(laws)}.</p>"
        f"<p>{n_pass} of {len(e.checks)} closed forms agree with the exact integration.</p>"
        "<table><thead><tr><th>quantity</th><th>closed form</th><th>eq.</th>"
        "<th>value</th><th>numeric</th><th>unit</th><th>rel. error</th><th>pass</th>"
        f"</tr></thead><tbody>{''.join(rows)}</tbody></table>"
        f"<figure>{e.figure_svg()}</figure>"
        "</div>"
    )
