"""One unit table (issue #19 item 4): every unit the tool writes is named in
:data:`crankbase.texts.UNITS` (international spelling → ``common.unit.<name>``), spelled in
each language by one catalogue key and read through :meth:`crankbase.texts.Texts.unit`;
the schema, the column-suffix tables, the sheets' rows and the template builder name
their units there, and no catalogue spells a unit a second time."""
from __future__ import annotations

import re
from pathlib import Path

import pytest
from babel.messages.pofile import read_po

from crankbase import texts as T

ROOT = Path(__file__).resolve().parent.parent


def _builder():
    """The template builder (``templates/build_engine_templates.py``, a script of the
    repository, not an installed module)."""
    import importlib.util

    spec = importlib.util.spec_from_file_location(
        "build_engine_templates", ROOT / "templates" / "build_engine_templates.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _schema_units():
    """{unit} of every key of every spec schema (the three files' and the synthesis')."""
    from crankbase import schema as S
    from linkage.synthesis_study import SCHEMA as SYNTH

    out = {}
    for s in S._schemas(None) + [SYNTH]:
        for tab in S._walk(s.tables):
            for k in tab.keys():
                if k.unit:
                    out.setdefault(k.unit, f"{s.name}: {k.text_key}")
    return out


def _table_units():
    """{unit: where} of every table of the reports that names a unit."""
    import dynamics.report as dr
    import engine.report.workbook as ew
    import linkage.report as lr
    from engine.symbols import MASS_INPUTS

    B = _builder()

    out = {}

    def add(unit, where):
        if unit:
            out.setdefault(unit, where)

    for suffix, unit in lr.COLUMN_UNITS.items():
        add(unit, f"linkage.report.COLUMN_UNITS[{suffix!r}]")
    for col, (_, unit) in lr._SIMPLE.items():
        add(unit, f"linkage.report._SIMPLE[{col!r}]")
    for suffix, unit in lr._UNIT_SUFFIXES:
        add(unit, f"linkage.report._UNIT_SUFFIXES[{suffix!r}]")
    for suffix, unit in dr._SUFFIX:
        add(unit, f"dynamics.report._SUFFIX[{suffix!r}]")
    for key, (_, unit) in MASS_INPUTS.items():
        add(unit, f"engine.symbols.MASS_INPUTS[{key!r}]")
    for name, kind in ew._TR_SHAPE.items():
        if isinstance(kind, tuple) and kind[0] == "rows":
            for key, unit in kind[1].items():
                add(unit, f"engine.report.workbook._TR_SHAPE[{name!r}][{key!r}]")
    for key, _, unit, _ in B.INPUTS + B.SUMMARY_VALUES:
        add(unit, f"templates: {key}")
    for key, _, unit in B.SUMMARY_EXTREMES:
        add(unit, f"templates: {key}")
    return out


def test_every_unit_the_schema_and_the_tables_name_is_in_the_one_table():
    """A unit spelled outside :data:`~crankbase.texts.UNITS` (a new "Nm" beside "N·m", a
    "deg" key unit where the reference writes "°") fails here, not in a report."""
    schema, tables = _schema_units(), _table_units()
    # the collectors see what they must: not an empty (and so always passing) check
    assert {"mm", "MPa", "°", "kg/m²", "kg·m²", "N·m/rad", "rpm"} <= set(schema)
    assert {"deg", "°", "m/s²", "N·m", "kW", "%", "cm²", "l"} <= set(tables)
    assert "deg" not in schema                     # the reference writes the sign
    unknown = {u: w for u, w in {**schema, **tables}.items() if u not in T.UNITS}
    assert not unknown, unknown


def test_every_unit_is_one_key_in_every_language():
    """:data:`~crankbase.texts.UNITS` and the ``common.unit.*`` keys are one set (no
    unit without its key, no key that no code can ask), the same in every catalogue; no
    second set of unit keys (``spec.unit.*``, ``dynamics.unit.*``, a sheet row's
    ``.unit``) is left."""
    names = list(T.UNITS.values())
    assert len(set(names)) == len(names), "two spellings share a key"
    for lang in T.catalogue_languages():
        keys = set()
        for path in sorted((T.LOCALE_DIR / lang).glob("*.po")):
            with path.open("rb") as fh:
                keys |= {m.id for m in read_po(fh) if m.id and isinstance(m.id, str)}
        units = {k[len("common.unit."):] for k in keys if k.startswith("common.unit.")}
        assert units == set(names), (lang, units ^ set(names))
        second = sorted(k for k in keys if re.search(r"(^|\.)unit\.", k)
                        and not k.startswith(("common.unit.", "plot.plans.unit.")))
        assert not second, (lang, second)
        # a sheet row's own unit: only the column heads "Unit" remain
        rows = sorted(k for k in keys if k.endswith(".unit") and k not in (
            "sheet.engine.head.unit", "sheet.dynamics.unit", "spec.column.unit"))
        assert not rows, (lang, rows)


def test_the_units_as_each_language_spells_them():
    """The spellings that differ by language or by use: the degree sign of the reference
    and the inputs sheets ("°") against the degree of a column head ("deg" in English,
    the sign in Russian and, as the Chinese textbooks' φ/(°), in Chinese); a moment of
    inertia kg·m² against a mass per area kg/m² (the two sets of keys once named them
    the other way round); rpm, litre."""
    ru, en, zh = T.texts("ru"), T.texts("en"), T.texts("zh")
    assert (en.unit("°"), ru.unit("°"), zh.unit("°")) == ("°", "°", "°")
    assert (en.unit("deg"), ru.unit("deg"), zh.unit("deg")) == ("deg", "°", "°")
    assert (en.unit("kg·m²"), ru.unit("kg·m²")) == ("kg·m²", "кг·м²")
    assert (en.unit("kg/m²"), ru.unit("kg/m²")) == ("kg/m²", "кг/м²")
    assert (en.unit("rpm"), ru.unit("rpm"), zh.unit("rpm")) == ("rpm", "мин⁻¹", "r/min")
    assert (en.unit("l"), ru.unit("l"), zh.unit("l")) == ("l", "л", "L")
    assert (en.unit("N·m·s/rad"), ru.unit("N·m·s/rad")) == ("N·m·s/rad", "Н·м·с/рад")
    assert en.unit("") == ru.unit("") == ""
    with pytest.raises(KeyError, match="not in crankbase.texts.UNITS"):
        en.unit("Nm")


def test_the_schema_and_the_column_heads_ask_the_one_table():
    """The spec reference's unit cell, a missing key's problem and the linkage's, the
    chain's and the dynamics' column heads spell their units by the one table."""
    from dynamics.report import column_label as dynamics_label
    from engine.schema import SCHEMA
    from linkage.chain_report import chain_column_label
    from linkage.report import column_label

    keys = {k.name: k for tab in SCHEMA.tables for k in tab.keys()}
    assert keys["bore_mm"].unit_text("ru") == "мм"
    assert keys["vee_angle_deg"].unit_text("en") == "°"
    assert (keys["bore_mm"].wanted().render("ru")
            == T.texts("ru")("errors.wanted.key", label=keys["bore_mm"].label("ru"),
                             unit="мм"))
    assert column_label("phi_deg", "en") == ("φ", "°")
    assert column_label("B_vx_m_s", "ru") == ("VBx", "м/с")
    assert chain_column_label("omega_lever_rad_s", "ru") == ("ω lever", "рад/с")
    assert chain_column_label("theta_lever_deg", "en") == ("θ lever", "°")
    assert chain_column_label("R_crank_block_N", "zh") == ("R crank→block", "N")
    assert dynamics_label("phi_deg", "en") == "φ [deg]"
    assert dynamics_label("phi_deg", "ru") == "φ, °"
    assert dynamics_label("phi_deg", "zh") == "φ [°]"
    assert dynamics_label("J_red_kgm2", "ru").endswith(", кг·м²")


@pytest.mark.parametrize("lang", T.OFFERED)
def test_the_templates_unit_cells_are_the_builders_tables(lang):
    """The committed templates (``templates/engine_<lang>.xlsx``) hold in their unit
    columns what the builder's tables name, spelled by :meth:`Texts.unit`: the builder
    and the tables agree with the shipped files, cell by cell."""
    from openpyxl import load_workbook

    from crankbase.resources import template_path

    B = _builder()

    t = T.texts(lang)
    wb = load_workbook(template_path(f"engine_{lang}.xlsx"), read_only=True)
    inputs, summary = wb.worksheets[0], wb.worksheets[2]

    def cell(ws, r, c):
        v = ws.cell(r, c).value
        return "" if v is None else v

    for i, (key, _, unit, _) in enumerate(B.INPUTS, start=4):
        assert (cell(inputs, i, 1), cell(inputs, i, 5)) == (key, t.unit(unit))
    for i, (key, _, unit) in enumerate(B.SUMMARY_EXTREMES, start=4):
        assert (cell(summary, i, 1), cell(summary, i, 8)) == (key, t.unit(unit))
    r0 = 4 + len(B.SUMMARY_EXTREMES) + 1
    for i, (key, _, unit, _) in enumerate(B.SUMMARY_VALUES, start=r0 + 1):
        assert (cell(summary, i, 1), cell(summary, i, 5)) == (key, t.unit(unit))
    wb.close()
