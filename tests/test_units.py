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


# -- the templates name their units by the table: {unit[N·m]} ----------------------------

#: What may follow a unit's spelling: not a letter, digit or a unit's own continuation
#: (m → m/s, кг → кг·м², % → %% argparse's escaped percent in a help text).
_UNIT_END = r"(?![\w²³⁻¹·/%])"
#: Where a unit spelled in a template is none: (language, key) → the text at that place.
#: A new entry needs its reason.
_NOT_UNITS = {
    ("en", "linkage.key.mass_kg"): "{link} m{n}",                 # m: the mass's symbol
    ("ru", "torsion.col.swing_deg_of"): "{mass} с колебанием",    # с: «with»
    # N: the side force among the table's symbols (ΔPg, Pj, P, β, N, S, K, T, …)
    ("en", "cli.engine.description"): "β, N, S",
}


def _spellings(t):
    """Every spelling of a unit of :data:`~crankbase.texts.UNITS` in the language of
    ``t``, the longest first; with the ASCII stand-ins of the non-ASCII ones (N*m for
    N·m, kg*m^2 for kg·m²), which are the unit spelled a second time too."""
    spell = {t.unit(si) for si in T.UNITS if si != "-"}
    spell |= {s.replace("·", "*").replace("²", "^2").replace("³", "^3") for s in spell}
    return sorted(spell, key=len, reverse=True)


def _masked(template: str) -> str:
    """``template`` with every field a mark a character long (so that a place in it is
    the place in ``template``): ``\x02`` for a unit field, ``\x01`` for another (argparse's
    ``%(choices)s`` too); ``{{ }}`` are literal braces."""
    def mark(m):
        f = m.group(0)
        return f if f in ("{{", "}}") else (
            "\x02" if T.UNIT_FIELD.fullmatch(f) else "\x01") * len(f)

    masked = re.sub(r"\{\{|\}\}|\{[^{}]*\}", mark, template)
    return re.sub(r"%\(\w+\)[sd]", lambda m: "\x01" * len(m.group(0)), masked)  # argparse's


def _spelled_units(template: str, lang: str):
    """``[(unit, text)]``: each unit of :data:`~crankbase.texts.UNITS`, as ``lang`` spells
    it, that ``template`` writes outside a unit field where it is a unit: after a
    ``{field}`` or a number (:func:`_units_after_numbers`) or as a label's unit
    (:func:`_label_units`)."""
    return [(u, w) for u, w, _ in _found_units(template, lang)]


def _found_units(template: str, lang: str):
    """``[(unit, text, span)]`` of :func:`_spelled_units`, in order, each place once."""
    found = {span: (u, w, span) for u, w, span in _label_units(template, lang)
             + _units_after_numbers(template, lang)}
    return [found[span] for span in sorted(found)]


def _not_a_unit(lang, key, template, span):
    """Whether the unit found at ``span`` of ``template`` lies in a text of
    :data:`_NOT_UNITS` (a word or a symbol there, not the template's other units)."""
    text = _NOT_UNITS.get((lang, key))
    if not text:
        return False
    return any(i <= span[0] and span[1] <= i + len(text)
               for i in (m.start() for m in re.finditer(re.escape(text), template)))


def _units_after_numbers(template: str, lang: str):
    """``[(unit, text, span)]``: the units spelled after a ``{field}`` or a number (not
    one of an identifier, ``λ1``, ``J_kgm2``).  A field's format spec (``{x:.1%}``,
    ``{x:.3g}``) is no text; a unit inside a word (the «м» of «момент», the "s" of
    "steps"), a symbol before the number (N, J) are not after one."""
    masked = _masked(template)
    # (after a unit field comes no unit: «в {unit[MPa]} с коэффициентами», с: «with»)
    after = "(?:\x01|(?<![\\w.,\x01\x02])\\d+(?:[.,]\\d+)?)[\\])]?[ \u00a0\u202f]?"
    spell = _spellings(T.texts(lang))
    found = re.finditer(after + "(" + "|".join(map(re.escape, spell)) + ")" + _UNIT_END,
                        masked)
    return [(m.group(1), _context(masked, m.start(1), m.end(1)), m.span(1)) for m in found]


#: Before a label's unit: the start of the text (a word table's unit, "N·m", a head
#: "mm 列"), a comma (", " or the Chinese "，"), " in " (« в », "以 ",
#: "单位 "), an opening bracket (not one of a name: "f(x)"; the Chinese "（" after any
#: word), ")/" of a unit of units ((m/s)/mm), "and" after a unit field ("{unit[mm]} and N");
#: a space before a unit with a sign of its own (°, N·m, m/s: never a word).
_LABEL_BEFORE = (r"(^|, |，| in | в |以 |单位 |(?<![\w\x01\x02])[\[(]|（|\)/"
                 r"|(?<=\x02)(?: and | и | 和 )| )")
_IN = (" in ", " в ", "以 ", "单位 ", " and ", " и ", " 和 ")
#: After a unit that is a word alone (mm, с, N): the end of the label, a closing bracket,
#: a separator, an opening bracket — not a word («, с которого»), an equation (", N=T_N")
#: or a list going on with a symbol that is no unit.
_LABEL_AFTER = r"(?=$|[)\]）;；,，:：\n]| \(|（)"
_CLOSES = {"[": "]", "(": ")", "（": "）"}


def _label_units(template: str, lang: str):
    """``[(unit, text, span)]``: the units a label writes after its name, not after a
    number: "f, Hz", "φ, °", «Частота f, Гц», "频率 f，Hz", "Pc [bar]", "φ [deg]", "(N)",
    "in mm", "(m/s)/mm".  After a bracket the unit closes it; after a comma or " in " a
    unit that is a word alone ("m", «с») ends the label or is followed by a separator,
    one with a sign of its own (°, ·, /, %) is a unit wherever it stands; a symbol in an
    equation ("(J = m·D²/4)", "T, N=T_N") is none."""
    masked = _masked(template)
    spell = _spellings(T.texts(lang))
    pattern = _LABEL_BEFORE + "(" + "|".join(map(re.escape, spell)) + ")" + _UNIT_END
    out = []
    for m in re.finditer(pattern, masked):
        before, unit = m.group(1), m.group(2)
        rest = masked[m.end(2):]
        word = re.fullmatch(r"[^\W\d_]+", unit) is not None  # a word alone: m, мм, N, с
        if before in _CLOSES:
            ok = rest.startswith(_CLOSES[before])
        elif before == "":                  # the whole text ("N·m"), or a unit's sign first
            ok = rest == "" or not word
        elif before == " ":                 # a sign of its own: "曲轴转角 °", "units N·m"
            ok = not word
        elif before == ")/":
            ok = True
        elif word:
            ok = re.match(_LABEL_AFTER, rest) is not None or (
                before in _IN and not re.match(r"\s*[=≈≳<>+−-]", rest))
        else:                                           # °, N·m, Н/мм, %
            ok = True
        if ok:
            out.append((unit, _context(masked, m.start(2), m.end(2)), m.span(2)))
    return out


def _context(masked, i, j):
    return re.sub("[\x01\x02]+", "{…}", masked[max(0, i - 12):j + 12])


def test_the_unit_check_sees_a_unit_where_it_is_one():
    """The check itself: a unit after a number or a field, a label's unit after its
    comma, in brackets or parentheses or after " in ", and an ASCII stand-in (N*m) are
    found, in every spelling; a unit field, a format spec, a word, a symbol, a symbol in
    an equation and an identifier are not."""
    def found(template, lang):
        return [u for u, _ in _spelled_units(template, lang)]

    assert found("Mкр.ср = {M:.1f} Н·м", "ru") == ["Н·м"]
    assert found("{p:.3f}МПа, {a:g}°, 2 с.", "ru") == ["МПа", "°", "с"]
    assert found("at {a} deg, {n} rpm, 100-150 mm", "en") == ["deg", "rpm", "mm"]
    assert found("{n} r/min，{x} %", "zh") == ["r/min", "%"]
    assert found("[{a}, {b}] mm; ({x}) kg", "en") == ["mm", "kg"]
    # the English terminal's ASCII stand-ins are the unit spelled a second time
    assert found("M {x} N*m, J = {J} kg*m^2", "en") == ["N*m", "kg*m^2"]
    # a label's unit: after its comma, in brackets, after " in ", a unit of units
    assert found("f, Hz", "en") == ["Hz"] and found("Частота f, Гц", "ru") == ["Гц"]
    assert found("频率 f，Hz", "zh") == ["Hz"] and found("φ, °", "ru") == ["°"]
    assert found("α, ° п.к.в.", "ru") == ["°"] and found("x, m", "en") == ["m"]
    assert found("Pc [bar]){w}", "en") == ["bar"] and found("φ [deg]", "en") == ["deg"]
    assert found("K, N (downward)", "en") == ["N"] and found("力（N）/ μP", "zh") == ["N"]
    assert found("lengths in m (e.g. O = [0, 0])", "en") == ["m"]
    assert found("forces in mm and N", "en") == ["mm"]
    assert found("forces in {unit[mm]} and N", "en") == ["N"]
    assert found("（力以 mm 和 N 表示", "zh") == ["mm"] and found("长度单位 m，", "zh") == ["m"]
    assert found("scale, (m/s)/mm (default", "en") == ["m/s", "mm"]
    assert found("μP, Н/мм =", "ru") == ["Н/мм"] and found("T, Н", "ru") == ["Н"]
    assert found("m r, x, г·мм", "ru") == ["г·мм"] and found("μ  [°]", "zh") == ["°"]
    assert found("N·m", "en") == ["N·m"] and found("мм", "ru") == ["мм"]
    for fine in ("Mкр.ср = {M:.1f} {unit[N·m]}", "{x:.1%} of it", "{x:.3g}", "{n} steps",
                 "момент {M} в точке", "N = {N}", "J_kgm2 с speed_ratio", "λ1 с шагом",
                 "(default: 0.2 %% of it)", "{x:.0f}{unit[°]}", "φ, {unit[°]}",
                 "f, {unit[Hz]}", "[{unit[bar]}]", "положение, с которого", "(с насосными",
                 "--map 'T, N=T_N'", "(J = m·D²/4)", "(m − mш.к)", "(m r)b", "f(s)",
                 "], m = {m}", "(s + l = p + q)", "(J ≳ {need})", "tg β, N = P",
                 "x_m, y_mm", "in {folder}", "flywheel m*D^2 = {x}",
                 "{n} и Н", "сила и Н", "mass and m", "J, {unit[kg·m²]}", "N = P",
                 "one of %(choices)s;", "в {unit[MPa]} с коэффициентами"):
        assert found(fine, "ru") == [] and found(fine, "en") == [], fine


@pytest.mark.parametrize("lang", T.catalogue_languages())
def test_no_template_spells_a_unit_that_the_table_names(lang):
    """Every template of every catalogue names a unit by a unit field (``{unit[N·m]}``),
    after a number or a field as well as a label's unit ("f, {unit[Hz]}"), so that a unit
    is spelled once per language (``common.unit.*``), the English terminal's too (no
    ASCII stand-in, N*m); only :data:`_NOT_UNITS` are words or symbols there."""
    bad = []
    for path in sorted((T.LOCALE_DIR / lang).glob("*.po")):
        with path.open("rb") as fh:
            for m in read_po(fh):
                if not m.id or not m.string:
                    continue
                key = m.id[0] if isinstance(m.id, (tuple, list)) else m.id
                if key.startswith("common.unit.") or key.endswith(".symbol"):
                    continue            # the table's own spellings; a symbol (m, g, L)
                forms = m.string if isinstance(m.string, (tuple, list)) else (m.string,)
                for form in forms:
                    for unit, where, span in _found_units(form, lang):
                        if _not_a_unit(lang, key, form, span):
                            continue
                        bad.append(f"{key}: {unit!r} in …{where}…")
    assert not bad, f"{lang}: write these units as {{unit[<SI>]}}:\n" + "\n".join(bad)

@pytest.mark.parametrize("lang", T.catalogue_languages())
def test_every_unit_field_names_a_unit_of_the_table(lang):
    """A unit field names a key of :data:`~crankbase.texts.UNITS` (else the text would be
    a KeyError when shown); no unit spelling holds a brace (it is written into a template
    still to be formatted); the catalogues use the fields (not a check of nothing)."""
    named = set()
    for path in sorted((T.LOCALE_DIR / lang).glob("*.po")):
        named |= set(T.UNIT_FIELD.findall(path.read_text(encoding="utf-8")))
    assert {"N·m", "MPa", "°", "rpm", "%"} <= named
    assert named <= set(T.UNITS), named - set(T.UNITS)
    t = T.texts(lang)
    assert not [si for si in T.UNITS if set("{}") & set(t.unit(si))]


def test_a_unit_field_is_the_unit_of_the_templates_language():
    """``{unit[…]}`` is written in the catalogue's spelling wherever a text is made: a call
    with fields, a text asked without fields (a plot's word table formatted later), a
    plural entry, a :class:`~crankbase.errors.Text` rendered later, the help read alone
    (``area_texts``), and an English text a language lacks (English units)."""
    from crankbase.errors import Text
    from crankbase.plot_texts import plot_words

    ru, en, zh = T.texts("ru"), T.texts("en"), T.texts("zh")
    assert ru("engine.summary.M_mean", M=12.345) == "  Mкр.ср                  12.35 Н·м  (один цилиндр)"
    assert en("torsion.summary.torque", M=1.5, section=2, speed=3000).count("N·m") == 1
    assert zh("torsion.summary.worst", speed=3000, mode=1, order=4.5, kind="-",
              beta=0.1).count("r/min") == 1
    # without fields: the unit written, the other fields left to the caller
    words = plot_words("ru", "train")
    assert words["mean"] == ru("plot.train.mean").replace("{unit[", "!") \
        and "Н·м" in words["mean"] and "{unit[" not in words["mean"]
    assert words["mean"].format(v=1.0).endswith("Н·м")
    # a plural entry (engine.summary.balance has three Russian forms)
    for n in (1, 3, 5):
        line = ru.n("engine.summary.balance", n, F=1.0, M=2.0, unbalanced="-")
        assert "Н·м" in line and "{" not in line, line
    # rendered later, in each language
    text = Text("errors.engine.bearings.loads_at_mm", {"value": 12.5, "value2": 0, "value3": 9})
    assert text.render("ru").count("мм") == text.render("en").count("mm") >= 1
    # the command line's help, read alone with its units
    help_ru = T.area_texts("ru", "cli")("cli.linkage.opt.mu_v")
    assert "100–150 мм" in help_ru and "{unit[" not in help_ru
    # a key the language lacks: the English text with English units
    fake = T.Texts("xx", T.texts("ru")._tr, frozenset({"common.unit.N_m"}), en)
    assert fake("plot.train.mean", v=2.0) == en("plot.train.mean", v=2.0)
    assert "N·m" in fake("plot.train.mean", v=2.0)


# -- one column-suffix table, the symbols the catalogue's -----------------------------------


def test_the_dynamics_column_heads_read_the_one_suffix_table(monkeypatch):
    """:func:`dynamics.report.column_label` finds a column's unit in
    :data:`linkage.report.COLUMN_UNITS` (no table of its own): the longest suffix that
    fits (rad/s² before rad/s before s), the degree of its one-cell head the word; a
    suffix added there is one it reads."""
    import linkage.report as lr
    from dynamics.report import column_label

    assert column_label("eps_rad_s2", "en") == "ε [rad/s²]"
    assert column_label("omega_rad_s", "ru") == "ω, рад/с"
    assert column_label("t_s", "ru") == "t, с"
    assert column_label("phi_rad", "en") == "φ [rad]"
    assert column_label("alpha_deg_const", "en") == "α [deg] (ω = const)"
    assert column_label("dJ_red_dphi_kgm2", "ru") == "dJп/dφ, кг·м²"
    assert column_label("W_J", "en") == "ΔE = ∫(M_d − M_c)dφ [J]"
    assert column_label("R12_x_N", "zh") == "R12_x [N]"
    monkeypatch.setitem(lr.COLUMN_UNITS, "kW", "kW")
    assert column_label("Ne_kW", "ru") == "Ne, кВт"


def test_the_symbols_are_the_catalogues(monkeypatch):
    """The symbols the Russian and the Latin textbooks write differently are catalogue
    keys (``linkage.symbol.*``, ``dynamics.symbol.*``): each language's own, chosen by
    filling the keys, not by code; the columns read them."""
    import dynamics.report as dr
    from crankbase import texts as texts_module
    from linkage.report import column_label

    assert column_label("M_drive_Nm", "ru") == ("Mур", "Н·м")
    assert column_label("M_drive_Nm", "en") == ("Mb", "N·m")
    assert column_label("position", "ru") == ("№", "")
    assert column_label("F_res_N", "zh") == ("Fr", "N")
    assert column_label("Fu3_x_N", "ru") == ("Fи3x", "Н")
    assert column_label("Mu4_Nm", "en") == ("Mi4", "N·m")
    assert dr.column_label("M_drive_Nm", "ru") == "Mд, Н·м"
    assert dr.column_label("M_drive_Nm", "ru", dr._SYMBOL_FORCES) == "Mур, Н·м"
    assert dr.column_label("M_drive_Nm_const", "en", dr._SYMBOL_FORCES) == \
        "M_b [N·m] (ω = const)"
    assert dr.column_label("R_N", "ru") == "Rшш, Н" and dr.column_label("R_N", "en") == "Rcp [N]"
    assert dr.column_label("M_resist_loads_Nm", "ru").startswith("Mс ")
    # a language's symbols are its catalogue's: another catalogue, other symbols
    ru = T.texts("ru")
    own = {"dynamics.symbol.J_red": "J*", "linkage.symbol.inertia_index": "ι"}
    words = {k: ru(k) for k in T.keys("ru")}
    words.update(own)
    fake = T.Texts("ru", T._AreaTranslations(words), frozenset(words), T.texts("en"))
    monkeypatch.setattr(texts_module, "texts", lambda lang="ru": fake)
    assert dr.column_label("J_red_kgm2", "ru") == "J*, кг·м²"
    assert column_label("Fu3_N", "ru") == ("Fι3", "Н")
    # every symbol key the code asks is in every offered language
    asked = set(dr._SYMBOL.values()) | set(dr._SYMBOL_FORCES.values()) | {
        f"linkage.symbol.{c}" for c in ("position", "M_drive_Nm", "M_res_Nm", "F_res_N",
                                        "inertia_index")}
    for lang in T.OFFERED:
        assert asked <= T.keys(lang), (lang, asked - T.keys(lang))


def test_the_inputs_sheet_takes_each_keys_unit_from_the_schema(tmp_path):
    """The linkage inputs sheet's unit cell is the unit the spec schema gives the key at
    that path (:meth:`crankbase.schema.Schema.key_of`), not a guess from the key's name:
    a placeholder table (``links.<link>``), an array's index, one point of a ``points``
    key, a key outside the schema (``[drawing]``) without a unit."""
    import linkage
    import linkage.report as lr
    from crankbase.resources import example_path
    from crankbase.schema import Key, Schema, Table
    from linkage.schema import CHAIN_SCHEMA, SCHEMA

    unit = {k: lr._spec_unit(k, SCHEMA) for k in (
        "mechanism.crank", "mechanism.ground_angle_deg", "mechanism.omega_rad_s",
        "links.coupler.mass_kg", "links.rocker.inertia_kg_m2", "links.coupler.points.C",
        "links.crank.cg", "load[1].at", "load[0].force_N", "load[0].resistance_Nm",
        "load[0].from_fraction", "analysis.positions", "analysis.crank_angles_deg",
        "drawing.mass", "mechanism.nothing", "links.crank")}
    assert unit == {
        "mechanism.crank": "m", "mechanism.ground_angle_deg": "°",
        "mechanism.omega_rad_s": "rad/s", "links.coupler.mass_kg": "kg",
        "links.rocker.inertia_kg_m2": "kg·m²", "links.coupler.points.C": "m",
        "links.crank.cg": "m", "load[1].at": "m", "load[0].force_N": "N",
        "load[0].resistance_Nm": "N·m", "load[0].from_fraction": "",
        "analysis.positions": "", "analysis.crank_angles_deg": "°", "drawing.mass": "",
        "mechanism.nothing": "", "links.crank": ""}
    # a chain's: the frame's points and a group's lengths are lengths too
    assert [lr._spec_unit(k, CHAIN_SCHEMA) for k in (
        "mechanism.frame.O", "group[1].lengths", "group[0].guide_angle_deg",
        "group[0].links")] == ["m", "m", "°", ""]
    # the schema's unit, whatever the name says (a suffix guess would give ° and "")
    own = Schema("x", (Table("t", (Key("a_deg", unit="rad"), Key("stroke", unit="mm"))),))
    assert (lr._spec_unit("t.a_deg", own), lr._spec_unit("t.stroke", own)) == ("rad", "mm")
    # the sheet itself, in Russian: each row's unit cell is its key's in the schema
    from openpyxl import load_workbook

    res = linkage.analyze(linkage.load_spec(example_path("ratchet.toml")))
    lr.write_workbook(res, tmp_path / "r.xlsx", lang="ru")
    wb = load_workbook(tmp_path / "r.xlsx", read_only=True)
    keys = dict(lr._spec_rows(dict(res.spec.raw)))
    rows = {r[0]: r[2] for r in wb.worksheets[0].iter_rows(min_row=4, values_only=True)
            if r[0] in keys}
    wb.close()
    assert rows["mechanism.crank"] == "м" and rows["links.crank.mass_kg"] == "кг"
    assert rows["links.rocker.inertia_kg_m2"] == "кг·м²"
    t = T.texts("ru")
    for key, cell in rows.items():
        k = SCHEMA.key_of(key)
        assert (cell or "") == t.unit(k.unit if k else ""), key
    assert len(rows) == len(keys) > 20
