"""Textbook symbols of the engine reports in Russian and in English.

Russian reports use the symbols of the Russian course texts (Колчин & Демидов; the course
manual of seed 003): ΔPг, Sш, Mкр, Rшш …  English reports use the English textbook
symbols below, with no Cyrillic letter; the correspondence table is printed once on the
Inputs sheet of the English workbook and in the README.  Plain data, no imports.
"""
from __future__ import annotations

__all__ = ["SYMBOLS", "MEANING_RU", "MASS_INPUTS", "sym", "symbol_set", "math_symbol", "correspondence",
           "to_english", "mass_inputs"]

#: key → (Russian symbol, English symbol, English meaning).
SYMBOLS = {
    "alpha": ("α", "α", "crank angle from TDC"),
    "beta": ("β", "β", "angle of the rod from the cylinder axis"),
    "p_gas": ("pг", "pg", "absolute gas pressure in the cylinder"),
    "dPg": ("ΔPг", "ΔPg", "gas force on the piston, (pg − p0)·Ap"),
    "Pj": ("Pj", "Pj", "inertia force of the reciprocating masses"),
    "P": ("P", "P", "total force on the piston pin"),
    "S": ("Sш", "S", "force along the connecting rod"),
    "N": ("N", "N", "side force of the piston on the cylinder wall"),
    "K": ("K", "K", "radial force on the crank pin"),
    "T": ("T", "T", "tangential force on the crank pin"),
    "M": ("Mкр", "M", "torque of one cylinder"),
    "Kr": ("Kr.ш", "Kr", "centrifugal force of the rotating part of the rod"),
    "R": ("Rшш", "Rcp", "resultant load on the crank pin"),
    "psi": ("Ψ", "Ψ", "direction of Rcp in the crank frame"),
    "L": ("Lш", "L", "connecting-rod length"),
    "area": ("Fп", "Ap", "piston area"),
    "mj": ("mj", "mj", "reciprocating mass, mp + mr,rec"),
    "m_piston": ("mп", "mp", "mass of the piston group"),
    "m_rod": ("mш", "mr", "mass of the connecting rod"),
    "m_rod_rec": ("mш.п", "mr,rec", "reciprocating part of the rod mass"),
    "m_rod_rot": ("mш.к", "mr,rot", "rotating part of the rod mass"),
    "m_crank": ("mк", "mc", "unbalanced rotating mass of the crank"),
    "v_mean": ("vп.ср", "vp,mean", "mean piston speed"),
    "pole_R": ("Oш", "Or", "pole of the crank-pin load diagram"),
    "p_peak_real": ("pzд", "pz,real", "real peak pressure of the rounded diagram"),
    "M_mean": ("Mкр.ср", "M mean", "mean torque of one cylinder"),
    "R_mean": ("Rшш.ср", "Rcp,mean", "mean crank-pin load"),
    "R_max": ("Rшш.max", "Rcp,max", "maximum crank-pin load"),
    "tdc": ("ВМТ", "TDC", "top dead centre"),
    "bdc": ("НМТ", "BDC", "bottom dead centre"),
    "fullness": ("φп", "φf", "fullness of the indicator diagram, pi/p′i"),
    "m_piston_area": ("m′п", "m′p", "mass of the piston group per unit piston area"),
    "m_rod_area": ("m′ш", "m′r", "mass of the connecting rod per unit piston area"),
    "M_max": ("Mкр.max", "M max", "maximum torque of one cylinder"),
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
    "m_piston_area": "масса поршневой группы, отнесённая к площади поршня",
    "m_rod_area": "масса шатуна, отнесённая к площади поршня",
    "M_max": "максимальный крутящий момент одного цилиндра",
}


#: ``[masses]`` keys of an engine spec → (symbol key of :data:`SYMBOLS`, SI unit in its
#: international spelling, spelled in the report's language by
#: :meth:`crankbase.texts.Texts.unit`); ``rod_small_end_fraction`` is the share mш.п/mш of
#: the rod mass at the piston pin.
MASS_INPUTS = {
    "reciprocating_kg": ("mj", "kg"), "rod_rotating_kg": ("m_rod_rot", "kg"),
    "piston_group_kg": ("m_piston", "kg"), "rod_kg": ("m_rod", "kg"),
    "piston_group_kg_m2": ("m_piston_area", "kg/m²"),
    "rod_kg_m2": ("m_rod_area", "kg/m²"),
    "rod_small_end_fraction": (("m_rod_rec", "m_rod"), ""),
    "crank_rotating_kg": ("m_crank", "kg"),
}


def symbol_set(lang: str) -> str:
    """Which symbols a report in ``lang`` uses, as its catalogue says
    (``common.format.symbols``): "ru" (the Russian textbook's) for Russian, "en" (Latin and
    Greek, no Cyrillic) for English and Chinese (the Chinese textbooks use the same Latin
    symbols).  ``"ru"`` and ``"en"`` themselves name the two sets (as
    :func:`sym` accepts them)."""
    from crankbase.texts import SYMBOL_SETS, texts

    return lang if lang in SYMBOL_SETS else texts(lang).symbols


def sym(key: str, lang: str) -> str:
    """The symbol ``key`` in the symbol set of ``lang`` (a language, or a set: "ru" or
    "en", :func:`symbol_set`)."""
    ru, en, _ = SYMBOLS[key]
    return {"ru": ru, "en": en}[symbol_set(lang)]


def math_symbol(key: str) -> str:
    """The English symbol ``key`` as matplotlib mathtext, its letters after the first as a
    subscript: "Rcp" → ``$R_{cp}$``, "ΔPg" → ``$\\Delta P_{g}$``, "mr,rot" → ``$m_{r,rot}$``
    (the same symbol as in the workbook, set as the textbook prints it)."""
    en = SYMBOLS[key][1]
    head = "\\Delta " if en.startswith("Δ") else ""
    body = en[1:] if head else en
    if " " in body:                                   # "M mean": a word after the symbol
        body, word = body.split(" ", 1)
        return f"${head}{_sub(body)}$ {word}"
    return f"${head}{_sub(body)}$"


def _sub(body):
    return body[0] + (f"_{{{body[1:]}}}" if len(body) > 1 else "")


def correspondence(lang="en"):
    """Rows (English symbol, Russian symbol, meaning in ``lang``) where the two differ; the
    meaning is ``sheet.engine.meaning.<key>`` of the text layer (the English one is
    :data:`SYMBOLS`' third item, the Russian one :data:`MEANING_RU`)."""
    from crankbase.texts import texts

    t = texts(lang)
    return [(en, ru, t(f"sheet.engine.meaning.{key}"))
            for key, (ru, en, what) in SYMBOLS.items() if ru != en]


def to_english(text: str) -> str:
    """``text`` with every Russian textbook symbol replaced by its English one (longest
    symbols first, so "Rшш.ср" becomes "Rcp,mean", not "Rcp.ср").  Only symbols are
    translated; words are the caller's business."""
    pairs = sorted(((ru, en) for ru, en, _ in SYMBOLS.values() if ru != en),
                   key=lambda p: -len(p[0]))
    for ru, en in pairs:
        text = text.replace(ru, en)
    return text


def mass_inputs(mass_source, lang="ru") -> str:
    """The masses of a spec as given (``{[masses] key: value}``), in textbook symbols with
    units: "mп = 0.5 кг; mш = 0.7 кг" (ru), "mp = 0.5 kg; mr = 0.7 kg" (en)."""
    from crankbase.texts import texts

    out = []
    for key, value in mass_source.items():
        what, si = MASS_INPUTS[key]
        name = ("/".join(sym(k, lang) for k in what) if isinstance(what, tuple)
                else sym(what, lang))
        unit = texts(lang).unit(si) if si else ""
        out.append(f"{name} = {value:g}" + (f" {unit}" if unit else ""))
    return "; ".join(out)
