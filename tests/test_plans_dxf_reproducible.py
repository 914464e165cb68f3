"""A DXF sheet of the same inputs is the same bytes in every run and under every hash seed
(issue #19 item 4): no save time, no random GUID, no CLASSES in the order of a set."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import ezdxf
import pytest

ROOT = Path(__file__).resolve().parent.parent

#: Writes the sheet of the ratchet's position 5 in each language asked for to its path
#: (argv: path, lang, path, lang ...; the Chinese sheet with its CJK text style too).
SCRIPT = """
import sys
import linkage, plans
from crankbase.resources import example_path
from plans import drawing
from plans.dxf import write_dxf
res = linkage.analyze(example_path("ratchet.toml"))
pps = plans.build_plans(res, [5])
for path, lang in zip(sys.argv[1::2], sys.argv[2::2]):
    write_dxf(drawing.layout_sheets(res, pps, lang, "A1")[0], path)
"""


def _write(seed, *path_lang):
    """The sheets ``(path, lang), ...`` written by one process under ``PYTHONHASHSEED =
    seed``: their bytes, in that order."""
    env = {**os.environ, "PYTHONHASHSEED": str(seed)}
    subprocess.run([sys.executable, "-c", SCRIPT, *(str(x) for pl in path_lang for x in pl)],
                   check=True, env=env, cwd=ROOT, capture_output=True, timeout=300)
    return [path.read_bytes() for path, _ in path_lang]


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """The Chinese sheet written under two hash seeds (two processes) and the English one
    under the first (the first process writes both: a process start less)."""
    tmp = tmp_path_factory.mktemp("dxf")
    # seeds 3 and 4 ordered ezdxf's CLASSES (LAYOUT, ACDBPLACEHOLDER) differently before
    a, en = _write(3, (tmp / "a.dxf", "zh"), (tmp / "en.dxf", "en"))
    b, = _write(4, (tmp / "b.dxf", "zh"))
    return {"a": a, "b": b, "en": en, "path": tmp / "a.dxf"}


def test_two_runs_with_different_hash_seeds_write_the_same_bytes(written):
    assert written["a"] == written["b"]


def test_the_dates_are_fixed_and_the_guids_name_the_content(written):
    lines = written["a"].decode("utf-8").splitlines()
    for var in ("$TDCREATE", "$TDUCREATE", "$TDUPDATE", "$TDUUPDATE"):
        at = lines.index(var)              # the header variable: its group code, its value
        assert float(lines[at + 2]) == 2451545.0, var    # ezdxf: 2000-01-01 as a julian day
    doc = ezdxf.readfile(written["path"])
    fingerprint, version = doc.header["$FINGERPRINTGUID"], doc.header["$VERSIONGUID"]
    zero = "{00000000-0000-0000-0000-000000000000}"
    assert len({fingerprint, version, zero}) == 3
    # a different drawing (the English sheet) has other GUIDs
    assert written["en"] != written["a"]
    assert fingerprint.encode() not in written["en"] and version.encode() not in written["en"]
    meta = doc.ezdxf_metadata()
    assert meta["CREATED_BY_EZDXF"] == meta["WRITTEN_BY_EZDXF"] == (
        f"{ezdxf.__version__} @ 2000-01-01T00:00:00+00:00")
    names = [c.dxf.name for c in doc.classes]
    assert names == sorted(names) and "LAYOUT" in names
    # the drawing itself is whole: the Chinese texts in their CJK style, the layers
    assert doc.styles.has_entry("GOST_CJK") and doc.layers.has_entry("VECTORS")
