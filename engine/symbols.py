"""Textbook symbols of the engine reports in Russian and in English.

Russian reports use the symbols of the Russian course texts (Колчин & Демидов; the course
manual of seed 003): ΔPг, Sш, Mкр, Rшш …  English reports use the English textbook
symbols below, with no Cyrillic letter; the correspondence table is printed once on the
Inputs sheet of the English workbook and in the README.  Plain data, no imports.
"""
from __future__ import annotations

__all__ = ["SYMBOLS", "MEANING_RU", "sym", "correspondence", "to_english"]

#: key → (Russian symbol, English symbol, English meaning).
SYMBOLS = {
    "alpha": ("α", "α", "crank angle from TDC"),
    "beta": ("β", "β", "angle of the rod from the cylinder axis"),
    "p_gas": ("pг", "pg", "absolute gas pressure in the cylinder"),
    "dPg": ("ΔPг", "ΔPg", "gas force on the piston, (pg − p0)·Ap"),
    "Pj": ("Pj", "Pj", "inertia force of the reciprocating masses"),
    "P": ("P", "P", "total force on the piston pin"),
    "S": ("Sш", "Srod", "force along the connecting rod"),
    "N": ("N", "N", "side force of the piston on the cylinder wall"),
    "K": ("K", "K", "radial force on the crank pin"),
    "T": ("T", "T", "tangential force on the crank pin"),
    "M": ("Mкр", "Mt", "torque of one cylinder"),
    "Kr": ("Kr.ш", "Kr,rod", "centrifugal force of the rotating part of the rod"),
    "R": ("Rшш", "Rpin", "resultant load on the crank pin"),
    "psi": ("Ψ", "ψ", "direction of Rpin in the crank frame"),
    "L": ("Lш", "L", "connecting-rod length"),
    "area": ("Fп", "Ap", "piston area"),
    "mj": ("mj", "mj", "reciprocating mass, mp + mrod,rec"),
    "m_piston": ("mп", "mp", "mass of the piston group"),
    "m_rod": ("mш", "mrod", "mass of the connecting rod"),
    "m_rod_rec": ("mш.п", "mrod,rec", "reciprocating part of the rod mass"),
    "m_rod_rot": ("mш.к", "mrod,rot", "rotating part of the rod mass"),
    "m_crank": ("mк", "mc", "unbalanced rotating mass of the crank"),
    "v_mean": ("vп.ср", "vp,mean", "mean piston speed"),
    "pole_R": ("Oш", "Opin", "pole of the crank-pin load diagram"),
    "p_peak_real": ("pzд", "pz,real", "real peak pressure of the rounded diagram"),
    "M_mean": ("Mкр.ср", "Mt,mean", "mean torque of one cylinder"),
    "R_mean": ("Rшш.ср", "Rpin,mean", "mean crank-pin load"),
    "R_max": ("Rшш.max", "Rpin,max", "maximum crank-pin load"),
    "tdc": ("ВМТ", "TDC", "top dead centre"),
    "bdc": ("НМТ", "BDC", "bottom dead centre"),
    "fullness": ("φп", "φf", "fullness of the indicator diagram, pi/p′i"),
}


#: key → the meaning in Russian (for the Russian workbook's symbol table).
MEANING_RU = {
    "alpha": "угол поворота кривошипа от ВМТ",
    "beta": "угол отклонения оси шатуна от оси цилиндра",
    "p_gas": "абсолютное давление газов в цилиндре",
    "dPg": "сила давления газов на поршень, (pг − p0)·Fп",
    "Pj": "сила инерции возвратно-поступательно движущихся масс",
    "P": "суммарная сила, действующая на поршневой палец",
    "S": "сила, действующая вдоль шатуна",
    "N": "боковая сила поршня на стенку цилиндра",
    "K": "радиальная сила на шатунной шейке",
    "T": "тангенциальная сила на шатунной шейке",
    "M": "крутящий момент одного цилиндра",
    "Kr": "центробежная сила вращающейся части шатуна",
    "R": "результирующая сила на шатунную шейку",
    "psi": "направление силы Rшш в системе координат кривошипа",
    "L": "длина шатуна",
    "area": "площадь поршня",
    "mj": "масса возвратно-поступательно движущихся частей, mп + mш.п",
    "m_piston": "масса поршневой группы",
    "m_rod": "масса шатуна",
    "m_rod_rec": "часть массы шатуна, отнесённая к поступательно движущимся",
    "m_rod_rot": "часть массы шатуна, отнесённая к вращающимся",
    "m_crank": "неуравновешенная вращающаяся масса кривошипа",
    "v_mean": "средняя скорость поршня",
    "pole_R": "полюс диаграммы нагрузки на шатунную шейку",
    "p_peak_real": "действительное максимальное давление скруглённой диаграммы",
    "M_mean": "средний крутящий момент одного цилиндра",
    "R_mean": "средняя сила на шатунную шейку",
    "R_max": "максимальная сила на шатунную шейку",
    "tdc": "верхняя мёртвая точка",
    "bdc": "нижняя мёртвая точка",
    "fullness": "коэффициент полноты индикаторной диаграммы, pi/p′i",
}


def sym(key: str, lang: str) -> str:
    """The symbol ``key`` in ``lang`` ("ru" or "en")."""
    ru, en, _ = SYMBOLS[key]
    return ru if lang == "ru" else en


def correspondence(lang="en"):
    """Rows (English symbol, Russian symbol, meaning in ``lang``) where the two differ."""
    return [(en, ru, what if lang == "en" else MEANING_RU[key])
            for key, (ru, en, what) in SYMBOLS.items() if ru != en]


def to_english(text: str) -> str:
    """``text`` with every Russian textbook symbol replaced by its English one (longest
    symbols first, so "Rшш.ср" becomes "Rpin,mean", not "Rpin.ср").  Only symbols are
    translated; words are the caller's business."""
    pairs = sorted(((ru, en) for ru, en, _ in SYMBOLS.values() if ru != en),
                   key=lambda p: -len(p[0]))
    for ru, en in pairs + [("Mкр.max", "Mt,max"), ("ср", "mean")]:
        text = text.replace(ru, en)
    return text
