"""Diesel-RK indicator import (engine.dieselrk, ``[pressure] file = "….ind"``).

The files are written here in the layout of a raw Diesel-RK export (the preamble
``Legend`` … ``Comment`` with a line per column, ``Names``, the header, ``Arrays``, rows
from Fi = 180° over one cycle, the firing TDC at Fi = 360°, CRLF line ends), as in the
public ``6DNK70x280.ind`` (staneuski/dualFuelEngine, etc/DRK2Py) and ``example.ind``
(staneuski/crankshaft, conrodForces); the numbers are the bundled D-240 example's own
indicator diagram, so the import must give exactly its force table.
"""
import copy
import math
import shutil
from pathlib import Path

import numpy as np
import pytest

import engine
from engine.dieselrk import read_ind
from engine.indicator import interpolate_periodic, volume_ratio

EXAMPLES = Path(__file__).parents[1] / "examples"
PREAMBLE = """ Legend
 2026-11-23 10-00-00 "D240-like" ||| Mode: #1 : Ne_max
 File : d240.ind

  INDICATOR DIAGRAM:
 Comment
 Fi          Crank angle, [deg]
 Pc          Cylinder pressure, [bar]
 Tc          Cylinder temperature, [K]
 V           Cylinder volume, [m3]
 Alf_w       Heat transfer coefficient (Woschni), [W/(m2 K)]
 P_1ring     Pressure behind the first ring, [bar]
 G_bb        Blow-by gas flow, [kg/s]
 P_pist      Piston position from BDC, [mm]
 x           Heat release fraction
Names
Fi        Pc        Tc        V         Alf_w     P_1ring   G_bb      P_pist    x
Arrays
"""


def d240():
    return engine.load_spec(EXAMPLES / "diesel_d240.toml")


def write_ind(path, fi, spec, tdc=360.0, preamble=True, rows=None, eol="\r\n"):
    """A Diesel-RK-style file of the D-240 diagram at the angles ``fi`` (file scale)."""
    alpha = np.mod(np.asarray(fi, float) - tdc + 360.0, spec.cycle_deg)
    p_bar = interpolate_periodic(alpha, np.array(spec.pressure.angle_deg),
                                 np.array(spec.pressure.p), spec.cycle_deg) / 1e5
    Vc = spec.Vh / (spec.epsilon - 1.0)
    V = Vc * volume_ratio(alpha, spec.lam, spec.epsilon)
    lines = (PREAMBLE.splitlines() if preamble else
             ["Fi        Pc        Tc        V         Alf_w     P_1ring   G_bb      "
              "P_pist    x", "Arrays"])
    for a, p, v in zip(fi, p_bar, V):
        lines.append(f" {a:6.1f}  {float(p)!r:>20}     394.8    {v:.6E}    207.7   1.5737"
                     "      0.54144E-03    0.000  0.20000E+26")
    if rows is not None:
        lines = rows(lines)
    Path(path).write_bytes((eol.join(lines) + eol + " " + eol).encode("utf-8"))


def spec_with(tmp_path, name, **pressure):
    shutil.copy(EXAMPLES / "diesel_d240.toml", tmp_path / "e.toml")
    d = engine.spec.read_toml(tmp_path / "e.toml")[0]
    d = copy.deepcopy(d)
    d["pressure"] = dict(file=name, **pressure)
    return engine.load_spec(d, base_dir=tmp_path)


def test_volume_ratio_of_the_fixture_is_least_at_tdc():
    s = d240()
    vr = volume_ratio(np.array([0.0, 180.0, 360.0]), s.lam, s.epsilon)
    assert vr[0] == pytest.approx(1.0) and vr[2] == pytest.approx(1.0)
    assert vr[1] == pytest.approx(s.epsilon)


def test_diesel_rk_file_gives_the_same_table_as_the_csv(tmp_path):
    ref = d240()
    write_ind(tmp_path / "d240.ind", np.arange(180.0, 901.0, 1.0), ref)
    spec = spec_with(tmp_path, "d240.ind")
    assert spec.pressure_source == "file"
    a = np.arange(0.0, 720.0, 0.5)
    t, t_ref = engine.force_table(spec, a), engine.force_table(ref, a)
    for col in ("p_gas_MPa", "P_N", "T_N", "R_N"):
        assert np.allclose(t[col], t_ref[col], rtol=1e-12,
                           atol=1e-12 * np.abs(t_ref[col]).max()), col
    # the rows landed at α = Fi mod 720: Fi = 366 is α = 366
    assert spec.pressure.angle_deg[0] == 0.0 and spec.pressure.angle_deg[-1] == 719.0
    assert len(spec.pressure.angle_deg) == 720
    assert spec.pressure_file == (tmp_path / "d240.ind").resolve()


def test_another_origin_is_shifted(tmp_path):
    """The same diagram written with the firing TDC at Fi = 0 (Fi = −180 … 540)."""
    ref = d240()
    write_ind(tmp_path / "z.ind", np.arange(-180.0, 541.0, 2.0), ref, tdc=0.0)
    spec = spec_with(tmp_path, "z.ind", firing_tdc_deg=0.0)
    a = np.arange(0.0, 720.0, 2.0)
    assert np.allclose(engine.force_table(spec, a)["p_gas_MPa"],
                       engine.force_table(ref, a)["p_gas_MPa"], rtol=1e-12)
    # without the key: Fi = 360 is then the gas-exchange TDC, caught by the pressure peak
    with pytest.raises(engine.EngineSpecError,
                       match=r"pressure\.firing_tdc_deg: z\.ind: the pressure peak .* is "
                             r"348° from the firing TDC Fi = 360"):
        spec_with(tmp_path, "z.ind")
    # an origin off by 90°: the volume is least elsewhere
    with pytest.raises(engine.EngineSpecError,
                       match=r"pressure\.firing_tdc_deg: z\.ind: the cylinder volume V is "
                             r"least at Fi = 0 \(line 109\), not at the firing TDC Fi = 90"):
        spec_with(tmp_path, "z.ind", firing_tdc_deg=90.0)


def test_origin_on_the_gas_exchange_tdc_is_refused(tmp_path):
    ref = d240()
    write_ind(tmp_path / "g.ind", np.arange(180.0, 901.0, 1.0), ref)
    with pytest.raises(engine.EngineSpecError, match="that is the gas-exchange TDC"):
        spec_with(tmp_path, "g.ind", firing_tdc_deg=720.0)


def test_file_without_preamble_and_lf_line_ends(tmp_path):
    """The trimmed layout of staneuski/crankshaft's example.ind (header, Arrays, rows)."""
    ref = d240()
    write_ind(tmp_path / "t.ind", np.arange(180.0, 901.0, 1.0), ref, preamble=False,
              eol="\n")
    a, p = read_ind(tmp_path / "t.ind", 720.0)
    assert a[0] == 0.0 and len(a) == 720


@pytest.mark.parametrize("damage, message", [
    (lambda L: L[:-300], r"bad\.ind line 439: the data end at Fi = 600, 420° after the "
                         r"first row .*truncated file"),
    (lambda L: L[:40] + [L[40][:30]] + L[41:], r"bad\.ind line 41: 2 values, the header "
                                               r"has 9 columns"),
    (lambda L: L[:50] + [L[50].replace("394.8", "39x.8")] + L[51:],
     r"bad\.ind line 51: not a number"),
    (lambda L: [x for x in L if not x.startswith("Fi ")],
     r"bad\.ind: no column header found"),
    (lambda L: [x.replace("Pc ", "Pz ") if x.startswith("Fi ") else x for x in L],
     r"bad\.ind: no column header found .*line 17 reads 'Fi        Pz"),
    (lambda L: L[:60] + [L[61], L[60]] + L[62:], r"bad\.ind line 62: Fi = 222 does not "
                                                 r"increase"),
    (lambda L: L[:-1] + [L[-1].replace(L[-1].split()[1], "9.0", 1)],
     r"bad\.ind line 739: the last row .* differs from the first"),
])
def test_damaged_files_name_the_line(tmp_path, damage, message):
    write_ind(tmp_path / "bad.ind", np.arange(180.0, 901.0, 1.0), d240(), rows=damage)
    with pytest.raises(engine.EngineSpecError, match="pressure\\.file: " + message):
        spec_with(tmp_path, "bad.ind")


def test_two_stroke_file(tmp_path):
    """Diesel-RK two-stroke range Fi = 180 … 540, TDC at 360 → α = Fi mod 360."""
    p = tmp_path / "two.ind"
    fi = np.arange(180.0, 541.0, 1.0)
    pbar = 2.9 + 100.0 * np.exp(-((fi - 365.0) / 15.0) ** 2)
    pbar[-1] = pbar[0]
    V = 1.1 - np.cos(np.radians(fi - 360.0))
    lines = PREAMBLE.splitlines() + [
        f" {a:6.1f}  {q:.6f}     394.8    {v:.6E}    207.7   1.5737      0.5E-03    0.000"
        "  0.2E+26" for a, q, v in zip(fi, pbar, V)]
    p.write_text("\n".join(lines) + "\n")
    a, pa = read_ind(p, 360.0)
    assert a[0] == 0.0 and a[-1] == 359.0
    assert pa[int(np.argmax(pa))] == pytest.approx(pbar.max() * 1e5)
    assert a[int(np.argmax(pa))] == 5.0
    # a four-stroke file read for a two-stroke engine, and the other way round
    write_ind(tmp_path / "four.ind", np.arange(180.0, 901.0, 1.0), d240())
    with pytest.raises(engine.spec.SpecError, match="more than one cycle of 360°; is "
                                                    r"\[engine\] strokes right"):
        read_ind(tmp_path / "four.ind", 360.0)
    with pytest.raises(engine.spec.SpecError, match="a whole cycle of 720° is needed"):
        read_ind(p, 720.0)


def test_firing_tdc_key_only_with_an_ind_file():
    d = engine.spec.read_toml(EXAMPLES / "diesel_d240.toml")[0]
    d = copy.deepcopy(d)
    d["pressure"]["firing_tdc_deg"] = 360.0
    with pytest.raises(engine.EngineSpecError, match="pressure.firing_tdc_deg: only used "
                                                     "with a Diesel-RK file"):
        engine.load_spec(d, base_dir=EXAMPLES)


def test_cp1251_preamble_is_read(tmp_path):
    """Diesel-RK writes its Russian preamble in the Windows code page."""
    ref = d240()
    write_ind(tmp_path / "r.ind", np.arange(180.0, 901.0, 1.0), ref)
    raw = (tmp_path / "r.ind").read_text(encoding="utf-8")
    raw = raw.replace("Crank angle, [deg]", "Угол поворота коленчатого вала, [град.]")
    (tmp_path / "r.ind").write_bytes(raw.encode("cp1251"))
    a, p = read_ind(tmp_path / "r.ind", 720.0)
    assert math.isclose(p.max(), max(ref.pressure.p), rel_tol=1e-12)
