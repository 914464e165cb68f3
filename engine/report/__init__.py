"""The engine's reports, the words and the workbook around the computed results (no
physics here; openpyxl is imported only when a workbook is built):

- :mod:`engine.report.workbook`: the Excel report of the force table and the whole engine,
  filled from a template (:func:`build_workbook`, :func:`add_engine_sheets`,
  :func:`save_workbook`);
- :mod:`engine.report.bearing_sheets`: the bearing sheets of that workbook;
- :mod:`engine.report.summary`: the terminal summary's lines.
"""
from .workbook import (CHART_STYLES, KOLCHIN_SHEET, LANGS, TABLE2_FORCES, TABLE2_KEYS,
                       a4_setup, add_engine_sheets, build_workbook, input_values,
                       readable_numbers, save_workbook)

__all__ = ["build_workbook", "add_engine_sheets", "save_workbook", "input_values",
           "TABLE2_FORCES", "TABLE2_KEYS", "LANGS", "KOLCHIN_SHEET", "CHART_STYLES",
           "a4_setup", "readable_numbers"]
