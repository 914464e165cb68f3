"""Build the Excel templates of the engine report: ``engine_ru.xlsx`` and ``engine_en.xlsx``.

The templates own the look (fonts, borders, merged two-row headers "мм | Н" per force as
in the textbook's Table 2, column widths, number formats) and every word of text; the
code (:mod:`engine.report`) only fills values, matched by the keys in the hidden column
A of the Inputs and Summary sheets, and adds the charts.

Run from the repository root after changing the layout::

    python templates/build_engine_templates.py
"""
from __future__ import annotations

from pathlib import Path

from openpyxl import Workbook
from openpyxl.styles import Alignment, Border, Font, PatternFill, Side
from openpyxl.utils import get_column_letter

HERE = Path(__file__).resolve().parent

#: Sheet names (the report looks sheets up by position, so names may differ per language).
SHEETS = {
    "ru": ("Исходные данные", "Таблица 2", "Итоги", "Данные", "Графики"),
    "en": ("Inputs", "Table 2", "Summary", "Data", "Charts"),
}

TITLE = {
    "ru": ("Исходные данные и производные величины",
           "Таблица 2 – Результаты вычисления сил, действующих в кривошипно-шатунном механизме",
           "Итоги: экстремумы и средние значения за цикл",
           "Данные расчёта (как в forces.csv, полная точность)"),
    "en": ("Inputs and derived quantities",
           "Table 2 – Forces acting in the crank mechanism",
           "Summary: extremes and cycle means",
           "Computed data (as in forces.csv, full precision)"),
}

# (key, ru label, en label, symbol, ru unit, en unit, number format)
INPUTS = [
    ("name", "Двигатель", "Engine", "", "", "", "@"),
    ("strokes", "Тактность", "Strokes per cycle", "τ", "", "", "0"),
    ("cylinders", "Число цилиндров", "Number of cylinders", "i", "", "", "0"),
    ("bore_mm", "Диаметр цилиндра", "Cylinder bore", "D", "мм", "mm", "0.0##"),
    ("stroke_mm", "Ход поршня", "Piston stroke", "S", "мм", "mm", "0.0##"),
    ("R_mm", "Радиус кривошипа", "Crank radius", "R = S/2", "мм", "mm", "0.0##"),
    ("L_mm", "Длина шатуна", "Connecting-rod length", "Lш", "мм", "mm", "0.0##"),
    ("lam", "Отношение радиуса кривошипа к длине шатуна", "Crank radius to rod length",
     "λ = R/Lш", "", "", "0.0000"),
    ("speed_rpm", "Частота вращения коленчатого вала", "Crankshaft speed", "n", "мин⁻¹",
     "rpm", "0"),
    ("omega", "Угловая скорость", "Angular velocity", "ω = πn/30", "рад/с", "rad/s",
     "0.00"),
    ("v_mean", "Средняя скорость поршня", "Mean piston speed", "vп.ср = Sn/30", "м/с",
     "m/s", "0.00"),
    ("p0_MPa", "Давление в картере", "Crankcase pressure", "p0", "МПа", "MPa", "0.000"),
    ("area_cm2", "Площадь поршня", "Piston area", "Fп = πD²/4", "см²", "cm²", "0.00"),
    ("Vh_l", "Рабочий объём цилиндра", "Displacement of one cylinder", "Vh = Fп·S", "л",
     "l", "0.0000"),
    ("compression_ratio", "Степень сжатия", "Compression ratio", "ε", "", "", "0.00"),
    ("acceleration", "Ускорение поршня", "Piston acceleration", "j", "", "", "@"),
    ("mass_input", "Массы (как заданы)", "Masses (as given)", "", "", "", "@"),
    ("mj", "Масса возвратно-поступательно движущихся частей", "Reciprocating mass",
     "mj = mп + mш.п", "кг", "kg", "0.000"),
    ("m_rod_rot", "Масса шатуна, отнесённая к вращающимся массам",
     "Rotating part of the rod mass", "mш.к", "кг", "kg", "0.000"),
    ("m_crank_rot", "Неуравновешенная вращающаяся масса кривошипа",
     "Rotating mass of the crank", "mк", "кг", "kg", "0.000"),
    ("Kr", "Центробежная сила вращающейся части шатуна",
     "Centrifugal force of the rotating part of the rod", "Kr.ш = −mш.к·R·ω²", "Н", "N",
     "0.0"),
    ("mu_P", "Масштаб сил", "Force scale", "μP", "Н/мм", "N/mm", "0.###"),
    ("step_deg", "Шаг таблицы", "Table step", "Δα", "°", "deg", "0.###"),
    ("extra_angles", "Дополнительные углы", "Extra angles", "", "°", "deg", "@"),
    ("pressure_source", "Индикаторная диаграмма", "Indicator diagram", "pг(α)", "", "",
     "@"),
    ("cycle_kind", "Цикл", "Cycle", "", "", "", "@"),
    ("pa", "Давление в конце впуска", "Pressure at the end of intake", "pa", "МПа", "MPa",
     "0.000"),
    ("pr", "Давление остаточных газов", "Residual-gas pressure", "pr", "МПа", "MPa",
     "0.000"),
    ("n1", "Показатель политропы сжатия", "Compression polytropic index", "n1", "", "",
     "0.000"),
    ("n2", "Показатель политропы расширения", "Expansion polytropic index", "n2", "", "",
     "0.000"),
    ("pc", "Давление в конце сжатия", "Pressure at the end of compression",
     "pc = pa·ε^n1", "МПа", "MPa", "0.000"),
    ("pz", "Максимальное давление цикла (расчётное)", "Maximum cycle pressure (calculated)",
     "pz", "МПа", "MPa", "0.000"),
    ("lambda_z", "Степень повышения давления", "Pressure-rise ratio", "λz = pz/pc", "", "",
     "0.000"),
    ("rho", "Степень предварительного расширения", "Pre-expansion ratio", "ρ", "", "",
     "0.000"),
    ("rounding", "Скругление диаграммы", "Diagram rounding", "", "", "", "@"),
    ("advance_deg", "Угол опережения зажигания (впрыска) до ВМТ",
     "Ignition (injection) advance before TDC", "θ", "°", "deg", "0.#"),
    ("pc_factor", "Давление в ВМТ в конце сжатия, доля pc", "Pressure at TDC, share of pc",
     "pc″/pc", "", "", "0.00"),
    ("peak_factor", "Действительное максимальное давление, доля pz",
     "Real peak pressure, share of pz", "pzд/pz", "", "", "0.00"),
    ("peak_after_tdc_deg", "Угол действительного максимума давления после ВМТ",
     "Angle of the real peak after TDC", "", "°", "deg", "0.#"),
    ("exhaust_opening_deg", "Открытие выпускного клапана до НМТ",
     "Exhaust valve opening before BDC", "", "°", "deg", "0.#"),
    ("intake_opening_deg", "Открытие впускного клапана до ВМТ",
     "Intake valve opening before TDC", "", "°", "deg", "0.#"),
    ("exhaust_closing_deg", "Закрытие выпускного клапана после ВМТ",
     "Exhaust valve closing after TDC", "", "°", "deg", "0.#"),
    ("pi_theory", "Среднее индикаторное давление нескруглённой диаграммы",
     "Indicated mean pressure of the unrounded diagram", "p′i", "МПа", "MPa", "0.0000"),
    ("pi", "Среднее индикаторное давление диаграммы (с насосными ходами)",
     "Indicated mean pressure of the diagram (pumping loop included)", "pi = ∮p dV / Vh",
     "МПа", "MPa", "0.0000"),
    ("power_i", "Индикаторная мощность одного цилиндра", "Indicated power of one cylinder",
     "Ni = pi·Vh·n/(30τ)", "кВт", "kW", "0.00"),
]

CONVENTIONS = {
    "ru": [
        "Условные обозначения и знаки",
        "α – угол поворота кривошипа от ВМТ по направлению вращения; для четырёхтактного "
        "двигателя 0…720°, α = 0 в ВМТ начала впуска (ВМТ сгорания при 360°).",
        "pг – абсолютное давление газов; ΔPг = (pг − p0)·Fп; Pj = −mj·j; P = ΔPг + Pj; "
        "силы по оси цилиндра положительны, если направлены к оси коленчатого вала.",
        "j = Rω²(cos α + λ cos 2α) (двучленная формула) или точное ускорение (по группе "
        "Ассура RRP) – см. строку «Ускорение поршня».",
        "β – угол отклонения оси шатуна от оси цилиндра, β > 0 при 0 < α < 180°.",
        "Sш = P/cos β – сила по шатуну, положительна при сжатии шатуна.",
        "N = P·tg β – боковая сила поршня на стенку цилиндра, положительна, если её момент "
        "относительно оси коленчатого вала направлен против вращения.",
        "K = P·cos(α+β)/cos β – радиальная сила, положительна к оси коленчатого вала; "
        "T = P·sin(α+β)/cos β – тангенциальная сила, положительна по вращению; Mкр = T·R.",
        "Kr.ш = −mш.к·R·ω² (направлена от оси вала); Rшш = √(T² + (K + Kr.ш)²) – сила, "
        "действующая на шатунную шейку.",
        "Ψ = atan2(T, K + Kr.ш) – угол силы Rшш в системе координат кривошипа: 0° – вдоль "
        "кривошипа к оси вала, положительный по направлению вращения, (−180°, 180°].",
        "Силы в мм чертежа = сила в Н / μP. Значения хранятся с полной точностью; формат "
        "ячеек влияет только на отображение.",
        "Кинематика и сила на шатунной шейке получены по группам Ассура I(1,2) → II(3,4) "
        "(кривошип и диада RRP); формулы таблицы (N = P tg β, K, T, Sш) – их проверка.",
    ],
    "en": [
        "Symbols and sign conventions",
        "α – crank angle from TDC in the direction of rotation; four-stroke: 0…720°, "
        "α = 0 at the TDC that starts intake (combustion TDC at 360°).",
        "pг – absolute gas pressure; ΔPг = (pг − p0)·Fп; Pj = −mj·j; P = ΔPг + Pj; forces "
        "along the cylinder axis are positive towards the crankshaft axis.",
        "j = Rω²(cos α + λ cos 2α) (two-term formula) or the exact acceleration (from the "
        "RRP Assur group) – see the row 'Piston acceleration'.",
        "β – angle of the rod axis from the cylinder axis, β > 0 for 0 < α < 180°.",
        "Sш = P/cos β – rod force, positive when the rod is compressed.",
        "N = P·tg β – side force of the piston on the cylinder wall, positive when its "
        "moment about the crankshaft axis opposes the rotation.",
        "K = P·cos(α+β)/cos β – radial force, positive towards the crankshaft axis; "
        "T = P·sin(α+β)/cos β – tangential force, positive in the direction of rotation; "
        "Mкр = T·R.",
        "Kr.ш = −mш.к·R·ω² (outwards); Rшш = √(T² + (K + Kr.ш)²) – the load on the crank "
        "pin.",
        "Ψ = atan2(T, K + Kr.ш) – direction of Rшш in the crank frame: 0° along the crank "
        "towards the crankshaft axis, positive in the direction of rotation, (−180°, 180°].",
        "Forces in mm of the drawing = force in N / μP. Values are stored at full "
        "precision; cell formats change only how they are shown.",
        "Kinematics and the crank-pin force come from the Assur groups I(1,2) → II(3,4) "
        "(crank and RRP dyad); the table formulas (N = P tg β, K, T, Sш) check them.",
    ],
}

# Table 2: (symbol, ru unit of N column, en unit)
FORCES = ["ΔPг", "Pj", "P", "Sш", "N", "K", "T", "Rшш"]

# Summary rows: (key, ru label, en label, symbol, unit ru, unit en, format)
SUMMARY_EXTREMES = [
    ("P_N", "Суммарная сила", "Total piston force", "P", "Н", "N"),
    ("S_N", "Сила по шатуну", "Rod force", "Sш", "Н", "N"),
    ("N_N", "Боковая сила", "Side force", "N", "Н", "N"),
    ("K_N", "Радиальная сила", "Radial force", "K", "Н", "N"),
    ("T_N", "Тангенциальная сила", "Tangential force", "T", "Н", "N"),
    ("M_Nm", "Крутящий момент цилиндра", "Torque of one cylinder", "Mкр", "Н·м", "N·m"),
    ("R_N", "Сила на шатунную шейку", "Crank-pin load", "Rшш", "Н", "N"),
]
SUMMARY_VALUES = [
    ("p_max_MPa", "Максимальное давление газов", "Peak gas pressure", "pг max", "МПа",
     "MPa", "0.000"),
    ("alpha_p_max_deg", "Угол максимального давления", "Angle of the peak pressure",
     "α(pг max)", "°", "deg", "0.0"),
    ("M_mean_Nm", "Средний крутящий момент цилиндра", "Mean torque of one cylinder",
     "Mкр.ср", "Н·м", "N·m", "0.00"),
    ("R_mean_N", "Средняя сила на шатунную шейку", "Mean crank-pin load", "Rшш.ср", "Н",
     "N", "0"),
    ("chi", "Коэффициент неравномерности нагрузки", "Load non-uniformity",
     "χ = Rшш.max/Rшш.ср", "", "", "0.000"),
    ("pi_MPa", "Среднее индикаторное давление диаграммы", "Indicated mean pressure",
     "pi", "МПа", "MPa", "0.0000"),
    ("power_i_kW", "Индикаторная мощность цилиндра", "Indicated power of one cylinder",
     "Ni", "кВт", "kW", "0.00"),
]

SUMMARY_NOTE = {
    "ru": "Экстремумы и средние значения вычислены по сетке 0,5° (вместе со строками "
          "таблицы 2), поэтому улавливают пики между строками таблицы; средние – по "
          "правилу трапеций за цикл. Mкр.ср и Rшш.ср – для одного цилиндра.",
    "en": "Extremes and means are computed on a 0.5° grid (together with the rows of "
          "Table 2), so peaks between table rows are caught; means by the trapezoid rule "
          "over the cycle. Mкр mean and Rшш mean are for one cylinder.",
}

def english_symbols(text):
    """An English template string with the Russian symbols replaced by the English ones of
    :mod:`engine.symbols` (the one table of symbols; imported here, in the build script,
    not at run time)."""
    from engine.symbols import to_english
    return to_english(text)


def _check_no_cyrillic(wb):
    import re

    cyrillic = re.compile("[\u0400-\u04ff]")
    for ws in wb.worksheets:
        for row in ws.iter_rows():
            for c in row:
                if isinstance(c.value, str) and cyrillic.search(c.value):
                    raise ValueError(f"Cyrillic left in the English template: {ws.title}!"
                                     f"{c.coordinate} {c.value!r}")


THIN = Side(style="thin", color="000000")
BORDER = Border(left=THIN, right=THIN, top=THIN, bottom=THIN)
HEAD_FILL = PatternFill("solid", fgColor="DDE4EE")
CENTER = Alignment(horizontal="center", vertical="center", wrap_text=True)
LEFT = Alignment(horizontal="left", vertical="center", wrap_text=True)


def _fonts(lang):
    """Body, bold, title and note fonts: the one family of every workbook
    (:data:`crankbase.workbook.FONT`) in both languages."""
    from crankbase.workbook import FONT as family

    return (Font(name=family, size=11), Font(name=family, size=11, bold=True),
            Font(name=family, size=13, bold=True), Font(name=family, size=10, italic=True))


def _fit_width(ws, orientation):
    """A4, one page wide, as many pages tall as needed."""
    ws.page_setup.paperSize = ws.PAPERSIZE_A4
    ws.page_setup.orientation = orientation
    ws.sheet_properties.pageSetUpPr.fitToPage = True
    ws.page_setup.fitToWidth = 1
    ws.page_setup.fitToHeight = 0


def _symbol_table(ws, r, lang, bold, body):
    """The table of symbols below the conventions: in the Russian template the Russian
    textbook symbol, the English report's symbol and the meaning; in the English one the
    English symbol and its meaning (no Cyrillic), every symbol of :mod:`engine.symbols`
    whose two forms differ."""
    from engine.symbols import correspondence

    from openpyxl.worksheet.pagebreak import Break

    ws.row_breaks.append(Break(id=r - 1))      # the table starts a page, with its title
    ru = lang == "ru"
    title = ("Обозначения русского и английского отчётов" if ru
             else "Symbols of this report (the Russian report and the README list the "
                  "Russian textbook symbols beside them)")
    c = ws.cell(r, 2, title)
    c.font = bold
    c.alignment = Alignment(wrap_text=True, vertical="top")
    ws.merge_cells(start_row=r, start_column=2, end_row=r, end_column=5)
    ws.row_dimensions[r].height = 15 if ru else 30
    head = (("Величина", "Русский отчёт", "Английский отчёт") if ru
            else ("Quantity", "Symbol"))
    for j, h in enumerate(head, start=2):
        c = ws.cell(r + 1, j, h)
        c.font, c.fill, c.border, c.alignment = bold, HEAD_FILL, BORDER, CENTER
    for i, (en, rus, what) in enumerate(correspondence(lang), start=r + 2):
        row = (what, rus, en) if ru else (what, en)
        for j, v in enumerate(row, start=2):
            c = ws.cell(i, j, v)
            c.font, c.border = body, BORDER
            c.alignment = LEFT if j == 2 else CENTER
        # a meaning longer than column B (50 characters wide) wraps onto a second line
        ws.row_dimensions[i].height = 15 if len(what) <= 55 else 30


def build(lang: str, path: Path) -> None:
    body, bold, title, note = _fonts(lang)
    L = 0 if lang == "ru" else 1
    wb = Workbook()
    ws_in = wb.active
    ws_in.title = SHEETS[lang][0]
    ws_t2 = wb.create_sheet(SHEETS[lang][1])
    ws_sum = wb.create_sheet(SHEETS[lang][2])
    ws_data = wb.create_sheet(SHEETS[lang][3])
    ws_ch = wb.create_sheet(SHEETS[lang][4])

    # ---------------------------------------------------------------- Inputs
    ws = ws_in
    ws["B1"] = TITLE[lang][0]
    ws["B1"].font = title
    heads = (("Величина", "Обозначение", "Значение", "Ед. изм.") if lang == "ru"
             else ("Quantity", "Symbol", "Value", "Unit"))
    ws["A3"] = "key"
    for j, h in enumerate(heads, start=2):
        c = ws.cell(3, j, h)
        c.font, c.fill, c.border, c.alignment = bold, HEAD_FILL, BORDER, CENTER
    for i, (key, ru, en, sym, u_ru, u_en, fmt) in enumerate(INPUTS, start=4):
        ws.cell(i, 1, key)
        for j, v in enumerate((ru if L == 0 else en, sym, None, u_ru if L == 0 else u_en),
                              start=2):
            c = ws.cell(i, j, v)
            c.font, c.border = body, BORDER
            c.alignment = LEFT if j in (2, 4) else CENTER
        ws.cell(i, 4).number_format = fmt
        ws.cell(i, 4).alignment = Alignment(horizontal="right", vertical="center",
                                            wrap_text=True)
    r = 4 + len(INPUTS) + 1
    for k, line in enumerate(CONVENTIONS[lang]):
        c = ws.cell(r + k, 2, line)
        c.font = bold if k == 0 else note
        c.alignment = Alignment(wrap_text=True, vertical="top")
        ws.merge_cells(start_row=r + k, start_column=2, end_row=r + k, end_column=5)
        ws.row_dimensions[r + k].height = 15 if k == 0 else 30
    r += len(CONVENTIONS[lang]) + 1
    _symbol_table(ws, r, lang, bold, body)
    ws.column_dimensions["A"].hidden = True
    for col, w in zip("BCDE", (50, 20, 40, 10)):
        ws.column_dimensions[col].width = w
    ws.freeze_panes = "B4"
    _fit_width(ws, "portrait")

    # ---------------------------------------------------------------- Table 2
    ws = ws_t2
    ws["A1"] = TITLE[lang][1]
    ws["A1"].font = title
    ws["A2"] = "μP, Н/мм =" if lang == "ru" else "μP, N/mm ="
    ws["A2"].font = bold
    ws["C2"].number_format = "0.###"
    ws["C2"].font = bold
    ws.merge_cells("A2:B2")
    mm, nn = ("мм", "Н") if lang == "ru" else ("mm", "N")
    ws.cell(3, 1, "α, °")
    ws.merge_cells(start_row=3, start_column=1, end_row=4, end_column=1)
    col = 2
    for sym in FORCES:
        ws.cell(3, col, sym)
        ws.merge_cells(start_row=3, start_column=col, end_row=3, end_column=col + 1)
        ws.cell(4, col, mm)
        ws.cell(4, col + 1, nn)
        col += 2
    ws.cell(3, col, "Mкр, Н·м" if lang == "ru" else "Mкр, N·m")
    ws.merge_cells(start_row=3, start_column=col, end_row=4, end_column=col)
    ws.cell(3, col + 1, "Ψ, °")
    ws.merge_cells(start_row=3, start_column=col + 1, end_row=4, end_column=col + 1)
    ncol = col + 1
    for rr in (3, 4):
        for cc in range(1, ncol + 1):
            c = ws.cell(rr, cc)
            c.font, c.fill, c.border, c.alignment = bold, HEAD_FILL, BORDER, CENTER
    # prototype data row (row 5): the report copies its styles to every row
    formats = ["0.##"] + ["0.0", "0"] * len(FORCES) + ["0.0", "0.0"]
    for cc in range(1, ncol + 1):
        c = ws.cell(5, cc)
        c.font, c.border = body, BORDER
        c.alignment = Alignment(horizontal="right")
        c.number_format = formats[cc - 1]
    ws.column_dimensions["A"].width = 8
    for cc in range(2, ncol + 1):
        ws.column_dimensions[get_column_letter(cc)].width = 9 if cc % 2 == 0 else 10
    ws.column_dimensions[get_column_letter(ncol - 1)].width = 10
    ws.column_dimensions[get_column_letter(ncol)].width = 8
    ws.freeze_panes = "B5"
    ws.print_title_rows = "3:4"
    _fit_width(ws, "landscape")

    # ---------------------------------------------------------------- Summary
    ws = ws_sum
    ws["B1"] = TITLE[lang][2]
    ws["B1"].font = title
    heads = (("Величина", "Обозначение", "Максимум", "α при max, °", "Минимум",
              "α при min, °", "Ед. изм.") if lang == "ru" else
             ("Quantity", "Symbol", "Maximum", "α at max, deg", "Minimum",
              "α at min, deg", "Unit"))
    ws["A3"] = "key"
    for j, h in enumerate(heads, start=2):
        c = ws.cell(3, j, h)
        c.font, c.fill, c.border, c.alignment = bold, HEAD_FILL, BORDER, CENTER
    for i, (key, ru, en, sym, u_ru, u_en) in enumerate(SUMMARY_EXTREMES, start=4):
        ws.cell(i, 1, key)
        vals = (ru if L == 0 else en, sym, None, None, None, None,
                u_ru if L == 0 else u_en)
        for j, v in enumerate(vals, start=2):
            c = ws.cell(i, j, v)
            c.font, c.border = body, BORDER
            c.alignment = LEFT if j == 2 else CENTER
        for j, fmt in zip((4, 5, 6, 7), ("0.0", "0.##", "0.0", "0.##")):
            ws.cell(i, j).number_format = fmt
            ws.cell(i, j).alignment = Alignment(horizontal="right")
    r0 = 4 + len(SUMMARY_EXTREMES) + 1
    heads2 = (("Величина", "Обозначение", "Значение", "Ед. изм.") if lang == "ru"
              else ("Quantity", "Symbol", "Value", "Unit"))
    for j, h in enumerate(heads2, start=2):
        c = ws.cell(r0, j, h)
        c.font, c.fill, c.border, c.alignment = bold, HEAD_FILL, BORDER, CENTER
    ws.cell(r0, 1, "key")
    for i, (key, ru, en, sym, u_ru, u_en, fmt) in enumerate(SUMMARY_VALUES, start=r0 + 1):
        ws.cell(i, 1, key)
        for j, v in enumerate((ru if L == 0 else en, sym, None, u_ru if L == 0 else u_en),
                              start=2):
            c = ws.cell(i, j, v)
            c.font, c.border = body, BORDER
            c.alignment = LEFT if j == 2 else CENTER
        ws.cell(i, 4).number_format = fmt
        ws.cell(i, 4).alignment = Alignment(horizontal="right")
    note_row = r0 + len(SUMMARY_VALUES) + 2
    c = ws.cell(note_row, 2, SUMMARY_NOTE[lang])
    c.font = note
    c.alignment = Alignment(wrap_text=True, vertical="top")
    ws.merge_cells(start_row=note_row, start_column=2, end_row=note_row, end_column=8)
    ws.row_dimensions[note_row].height = 45
    ws.column_dimensions["A"].hidden = True
    for col, w in zip("BCDEFGH", (44, 20, 13, 13, 13, 13, 9)):
        ws.column_dimensions[col].width = w
    _fit_width(ws, "landscape")

    # ---------------------------------------------------------------- Data
    ws = ws_data
    ws["A1"] = TITLE[lang][3]
    ws["A1"].font = title
    # row 3: the CSV header (filled by the code, styled here); row 4: prototype data row
    for cc in range(1, 18):
        c = ws.cell(3, cc)
        c.font, c.fill, c.border, c.alignment = bold, HEAD_FILL, BORDER, CENTER
        d = ws.cell(4, cc)
        d.font, d.border = body, BORDER
        d.number_format = "0.000"
        ws.column_dimensions[get_column_letter(cc)].width = 12
    ws.freeze_panes = "B4"
    ws.print_title_rows = "3:3"
    _fit_width(ws, "landscape")

    # ---------------------------------------------------------------- Charts
    ws_ch["A1"] = ("Графики сил по углу поворота кривошипа (по сетке итогов, 0,5°)"
                   if lang == "ru" else
                   "Forces over the crank angle (on the summary's 0.5° grid)")
    ws_ch["A1"].font = title
    ws_ch.merge_cells("A1:J1")
    _fit_width(ws_ch, "portrait")

    if lang == "en":
        for ws in wb.worksheets:
            for row in ws.iter_rows():
                for c in row:
                    if isinstance(c.value, str):
                        c.value = english_symbols(c.value)
        _check_no_cyrillic(wb)
    wb.properties.title = TITLE[lang][1]
    wb.properties.creator = "crankdyn"
    wb.save(path)


def main():
    for lang in ("ru", "en"):
        out = HERE / f"engine_{lang}.xlsx"
        build(lang, out)
        print("wrote", out)


if __name__ == "__main__":
    main()
