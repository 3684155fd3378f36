"""The machine-readable report, ``report.json``: every section and every check.

Layout::

    {"kresling_version", "mode": "quick" | "full", "created", "seconds", "command",
     "provenance": {"git_commit", "git_dirty", "kresling", "numpy", "scipy", "python",
                    "platform"},
     "checks_passed", "checks_total", "errors", "not_available",
     "sections": [{"key", "part", "title", "status", "outcome", "error", "seconds",
                   "summary", "checks_passed", "checks_total", "checks_text",
                   "checks": [{"name", "value", "reference", "source", "unit", "rtol",
                               "atol", "tolerance", "difference", "relative_difference",
                               "passed", "note", "synthetic"}],
                   "figures": [{"path", "caption"}], "tables": [{"path", "caption"}],
                   "views": [{"path", "caption"}]}]}

A view is an interactive plotly figure saved as JSON beside the page. A check with
``synthetic`` true tests a pipeline on synthetic data the model generated (a known truth
recovered), not the thesis's experiment. ``git_commit`` is ``null`` when the package does
not run from a git checkout; ``git_dirty`` says whether the checkout's tracked files
differed from that commit.

Paths are relative to the report's directory. Non-finite numbers are written as ``null``
(JSON has no NaN); such a check never passes.
"""

from __future__ import annotations

import json
import math
import os
from pathlib import Path

__all__ = ["report_document", "write_json", "check_record", "relative_path"]

def check_record(check) -> dict:
    """One check as a JSON-ready dict."""
    return {
        "name": check.name, "value": _number(check.value), "reference": _number(check.reference),
        "source": check.source, "unit": check.unit, "rtol": _number(check.rtol),
        "atol": _number(check.atol), "tolerance": _number(check.tolerance),
        "difference": _number(check.difference),
        "relative_difference": _number(check.relative_difference),
        "passed": bool(check.passed), "note": check.note,
        "synthetic": bool(check.synthetic),
    }


def report_document(report) -> dict:
    """The whole report (a :class:`kresling.report.build.Report`) as a JSON-ready dict."""
    return {
        "kresling_version": report.version,
        "mode": "quick" if report.quick else "full",
        "created": report.created,
        "seconds": report.seconds,
        "command": report.command,
        "provenance": dict(report.provenance),
        "checks_passed": report.checks_passed,
        "checks_total": report.checks_total,
        "errors": [run.chapter.key for run in report.errors],
        "not_available": [run.chapter.key for run in report.not_available],
        "sections": [_section_record(run, report.out_dir) for run in report.runs],
    }


def write_json(document: dict, path) -> Path:
    """Write a report document (:func:`report_document`) to ``path``; return the path."""
    path = Path(path)
    path.write_text(json.dumps(document, indent=1, allow_nan=False) + "\n", encoding="utf-8")
    return path


def _section_record(run, out_dir) -> dict:
    section = run.section
    return {
        "key": run.chapter.key, "part": run.chapter.part, "title": run.title,
        "status": run.status, "outcome": run.outcome, "error": run.error,
        "traceback": run.traceback,
        "seconds": run.seconds, "summary": section.summary if section else "",
        "checks_passed": run.checks_passed, "checks_total": len(run.checks),
        "checks_text": run.checks_text,
        "checks": [check_record(check) for check in run.checks],
        "figures": _files(section.figures, out_dir) if section else [],
        "tables": _files(section.tables, out_dir) if section else [],
        "views": _files(getattr(section, "views", []), out_dir) if section else [],
    }


def _files(items, out_dir) -> list:
    return [{"path": relative_path(path, out_dir), "caption": caption} for path, caption in items]


def relative_path(path, out_dir) -> str:
    """``path`` relative to the report's directory, with forward slashes."""
    return Path(os.path.relpath(Path(path).resolve(), Path(out_dir).resolve())).as_posix()


def _number(value):
    value = float(value)
    return value if math.isfinite(value) else None
