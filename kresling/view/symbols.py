"""The symbols of the views' texts, set with subscripts: ``K_B`` shown as K<sub>B</sub>.

Plotly draws a few HTML tags (``<sub>``, ``<sup>``, ``<b>``, ``<br>``) in titles, axis and
colour-bar titles, legends and hover text; LaTeX would need MathJax, which an offline page
does not have. The views therefore write their symbols in plain text (``K_B ratio``, as the
command line and the docstrings do) and pass every label through :func:`subscripted`.
"""

from __future__ import annotations

import re

__all__ = ["SYMBOLS", "subscripted"]

#: Plain-text symbols and how a view sets them (the facet angle as the character Ψ, which
#: plotly and every page show as it is; plotly knows few named HTML entities).
SYMBOLS = {"K_B": "K<sub>B</sub>", "K_ext": "K<sub>ext</sub>", "K_con": "K<sub>con</sub>",
           "Psi_ext": "Ψ<sub>ext</sub>", "Psi_con": "Ψ<sub>con</sub>"}

# A symbol on its own, not inside a word, a file name or a path ("table_K_B.csv" stays).
_SYMBOL = re.compile(r"(?<![\w/.])(" + "|".join(SYMBOLS) + r")(?![\w/])")


def subscripted(text: str) -> str:
    """``text`` with each symbol of :data:`SYMBOLS` set with its subscript.

    The text is not escaped: it may already hold plotly's tags (``<br>``, ``<sup>``).

    Parameters
    ----------
    text : str

    Returns
    -------
    str

    Examples
    --------
    >>> subscripted("K_B ratio K_ext / K_con")
    'K<sub>B</sub> ratio K<sub>ext</sub> / K<sub>con</sub>'
    >>> subscripted("Psi_ext<br>kb_ratio, table_K_B.csv")
    'Ψ<sub>ext</sub><br>kb_ratio, table_K_B.csv'
    """
    return _SYMBOL.sub(lambda match: SYMBOLS[match.group(1)], str(text))
