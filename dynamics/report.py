"""Workbook of a dynamics run (openpyxl): summary, motion table, forces under the true
motion beside the constant-speed ones, start-up.  Consumes computed results only."""
from __future__ import annotations

import math

__all__ = ["summary_rows", "build_workbook"]


def summary_rows(result: dict, lang="en"):
    """(label, value, unit) rows of the summary, in the report language."""
    ru = lang == "ru"
    m, fly = result["motion"], result["flywheel"]
    rows = [
        ("ωmax" if ru else "omega_max", m.omega_max, "рад/с" if ru else "rad/s"),
        ("ωmin" if ru else "omega_min", m.omega_min, "рад/с" if ru else "rad/s"),
        ("ωср = (ωmax + ωmin)/2" if ru else "omega_m = (max + min)/2", m.omega_mean,
         "рад/с" if ru else "rad/s"),
        ("ω средняя по времени" if ru else "time-mean omega", m.omega_time_mean,
         "рад/с" if ru else "rad/s"),
        ("δ", m.delta, "-"),
        ("ΔTmax" if ru else "dW_max", m.dW_max, "Дж" if ru else "J"),
        ("Jмаховика" if ru else "J_flywheel", m.J_flywheel, "кг·м²" if ru else "kg·m²"),
        ("Время цикла" if ru else "cycle time", m.cycle_time, "с" if ru else "s"),
    ]
    if m.M_drive_const is not None:
        if m.constant_role == "resist":
            rows.append(("Mс = const" if ru else "M_c (constant)", -m.M_drive_const,
                         "Н·м" if ru else "N·m"))
        else:
            rows.append(("Mд = const" if ru else "M_d (constant)", m.M_drive_const,
                         "Н·м" if ru else "N·m"))
    if fly is not None:
        rows += [
            ("δ заданный" if ru else "delta asked", fly.delta, "-"),
            ("ΔTmax при ω = const" if ru else "dW_max at constant speed", fly.dW_max,
             "Дж" if ru else "J"),
            ("Jc (среднее Jп)" if ru else "J_c (cycle mean of J_red)", fly.J_c,
             "кг·м²" if ru else "kg·m²"),
            ("Jмах = ΔTmax/(δ ωср²) − Jc" if ru else "J_F classic = dW/(delta w^2) - J_c",
             fly.J_classic, "кг·м²" if ru else "kg·m²"),
            ("Jмах точный" if ru else "J_F exact", fly.J_exact, "кг·м²" if ru else "kg·m²"),
        ]
    if result.get("startup") is not None:
        rows.append(("Время разгона" if ru else "start-up time", result["startup"].t_steady,
                     "с" if ru else "s"))
    return rows


def build_workbook(result: dict, lang="en"):
    """An openpyxl Workbook; raises ValueError if any number is not finite."""
    from openpyxl import Workbook
    from openpyxl.styles import Font

    wb = Workbook()
    ws = wb.active
    ws.title = "Итоги" if lang == "ru" else "Summary"
    ws.append(["Величина" if lang == "ru" else "Quantity",
               "Значение" if lang == "ru" else "Value", "Ед." if lang == "ru" else "Unit"])
    for row in summary_rows(result, lang):
        if not math.isfinite(row[1]):
            raise ValueError(f"summary value {row[0]} is not finite")
        ws.append(list(row))
    for c in ws[1]:
        c.font = Font(bold=True)
    ws.column_dimensions["A"].width = 36
    ws.column_dimensions["B"].width = 16

    def sheet(title, df):
        import numpy as np

        num = df.select_dtypes("number")
        if not np.all(np.isfinite(num.to_numpy())):
            raise ValueError(f"sheet {title}: a value is not finite")
        s = wb.create_sheet(title)
        s.append(list(df.columns))
        for c in s[1]:
            c.font = Font(bold=True)
        for rec in df.itertuples(index=False):
            s.append([float(v) for v in rec])

    sheet("Движение" if lang == "ru" else "Motion", result["motion"].table)
    if result.get("forces") is not None:
        sheet("Силы" if lang == "ru" else "Forces", result["forces"])
    if result.get("startup") is not None:
        sheet("Разгон" if lang == "ru" else "Startup", result["startup"].table)
    return wb
