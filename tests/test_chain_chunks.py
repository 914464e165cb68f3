"""The chain's tables are built chunk by chunk (issue #20, speed): rows on both sides of
every chunk boundary, and a short last chunk, are the rows of the same positions analysed
alone; ``course_tables=False`` leaves out exactly the magnitudes; the chain's motion and
reactions of a sweep longer than one chunk are those of the tables."""
from __future__ import annotations

import numpy as np
import pytest

import linkage
from crankbase.resources import example_path
from linkage.groups import CHUNK


@pytest.fixture(scope="module")
def shaper():
    return linkage.load_spec(example_path("shaper.toml"))


@pytest.fixture(scope="module")
def sweep(shaper):
    rng = np.random.default_rng(20)
    deg = rng.uniform(-400.0, 800.0, 2 * CHUNK + 5)     # unordered: a misplaced row shows
    return deg, linkage.analyze(shaper, crank_angles_deg=deg)


def _row(df, i):
    return df.drop(columns="position").iloc[i].to_numpy(float)


def test_rows_across_chunk_boundaries_are_the_positions_alone(shaper, sweep):
    deg, an = sweep
    rows = [0, 1, CHUNK - 1, CHUNK, CHUNK + 1, 2 * CHUNK - 1, 2 * CHUNK, len(deg) - 1, 12345]
    alone = linkage.analyze(shaper, crank_angles_deg=deg[rows])
    assert list(alone.kinematics.columns) == list(an.kinematics.columns)
    assert list(alone.forces.columns) == list(an.forces.columns)
    for k, i in enumerate(rows):
        for big, small in ((an.kinematics, alone.kinematics), (an.forces, alone.forces)):
            a, b = _row(big, i), _row(small, k)
            np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-9)
    # the cutting force acts in the sweep's working strokes only: both signs of the ram's
    # velocity and a non-zero resistance are among the rows compared
    assert np.count_nonzero(an.forces["F_res_N"].to_numpy()) > 1000


def test_tables_equal_the_whole_sweep_solved_at_once(sweep):
    """The motion and reactions of a sweep of three chunks are solved again at once; the
    tables, written chunk by chunk, hold the same numbers in the same rows."""
    deg, an = sweep
    assert np.array_equal(an.phi, np.radians(deg))
    E = an.motion.joints["E"]
    K, F = an.kinematics, an.forces
    np.testing.assert_allclose(K["x_E_m"], E.z.x, rtol=0, atol=1e-15)
    np.testing.assert_allclose(K["ay_E_m_s2"], E.a.y, rtol=1e-13, atol=1e-12)
    np.testing.assert_allclose(K["omega_lever_rad_s"], an.motion.omega("lever"), rtol=1e-13,
                               atol=1e-13)
    np.testing.assert_allclose(F["M_drive_Nm"], an.reactions.M_drive, rtol=1e-13, atol=1e-9)
    R = an.reactions.reactions[("frame", "lever")].force
    np.testing.assert_allclose(F["Rx_frame_lever_N"], R.x, rtol=1e-13, atol=1e-9)
    np.testing.assert_allclose(F["Ry_frame_lever_N"], R.y, rtol=1e-13, atol=1e-9)


def test_course_tables_false_leaves_out_exactly_the_magnitudes(shaper, sweep):
    deg, an = sweep
    lean = linkage.analyze(shaper, crank_angles_deg=deg, course_tables=False)
    for full, part in ((an.kinematics, lean.kinematics), (an.forces, lean.forces)):
        gone = [c for c in full.columns if c not in part.columns]
        assert [c for c in full.columns if c in part.columns] == list(part.columns)
        assert gone and all(c.startswith(("v_", "a_", "acor_", "R_")) for c in gone)
        for c in part.columns:
            assert np.array_equal(full[c].to_numpy(), part[c].to_numpy(), equal_nan=True), c
    K = lean.kinematics
    np.testing.assert_array_equal(an.kinematics["v_D_m_s"], np.hypot(K["vx_D_m_s"], K["vy_D_m_s"]))
    F = lean.forces
    np.testing.assert_array_equal(an.forces["R_lever_block_N"],
                                  np.hypot(F["Rx_lever_block_N"], F["Ry_lever_block_N"]))


def test_one_chunk_keeps_its_motion(shaper):
    an = linkage.analyze(shaper)                 # the plan of 12 positions
    assert an.motion is an.motion and len(an.motion.phi) == 12
    assert np.array_equal(an.forces["M_drive_Nm"].to_numpy(), an.reactions.M_drive)


def test_column_block_is_the_tables_storage():
    """The blocks the chunks are written into: columns × positions of float, every page
    mapped (a value written per page) and then overwritten by the tables' own numbers,
    rows of the same positions analysed alone, across the chunk boundaries of a
    four-bar too."""
    from linkage.groups import column_block

    b = column_block(3, 2 * CHUNK + 5)
    assert b.shape == (3, 2 * CHUNK + 5) and b.dtype == np.float64
    assert b.flags.c_contiguous and b.flags.writeable
    assert column_block(2, 0).shape == (2, 0)
    ratchet = linkage.load_spec(example_path("ratchet.toml"))
    deg = np.random.default_rng(9).uniform(-400.0, 800.0, 2 * CHUNK + 5)
    an = linkage.analyze(ratchet, crank_angles_deg=deg, course_tables=False)
    rows = [0, 512, CHUNK - 1, CHUNK, 2 * CHUNK, len(deg) - 1]     # 512: a page's start
    alone = linkage.analyze(ratchet, crank_angles_deg=deg[rows], course_tables=False)
    for big, small in ((an.kinematics, alone.kinematics), (an.forces, alone.forces)):
        for k, i in enumerate(rows):
            np.testing.assert_allclose(_row(big, i), _row(small, k), rtol=1e-12, atol=1e-9)
    # no row keeps a page's placeholder: the crank angle column is every angle given
    np.testing.assert_allclose(an.kinematics["phi_deg"], deg, rtol=1e-15, atol=0)


@pytest.mark.parametrize("name", ["shaper", "press6", "sixbar_rrr", "compressor_v",
                                  "shaper_cn"])
def test_later_chunks_written_into_the_rows_are_the_chunk_analysed_alone(name):
    """Every chunk after the first computes the crank pin, the links' points and centres
    of mass straight into the blocks' rows (linkage.chain.solve(out=…)); the first chunk
    writes fresh arrays.  A chunk's rows equal, bit for bit (uint64 views, NaN included),
    the same positions analysed alone as a first chunk, every column."""
    spec = linkage.load_spec(example_path(f"{name}.toml"))
    deg = 0.3 + (360.0 / (CHUNK + 700)) * np.arange(CHUNK + 700)
    an = linkage.analyze(spec, crank_angles_deg=deg, course_tables=False)
    alone = linkage.analyze(spec, crank_angles_deg=deg[CHUNK:], course_tables=False)
    for big, small in ((an.kinematics, alone.kinematics), (an.forces, alone.forces)):
        assert list(big.columns) == list(small.columns)
        for c in big.columns[1:]:
            a = big[c].to_numpy(float)[CHUNK:]
            assert np.array_equal(a.view(np.uint64), small[c].to_numpy(float).view(np.uint64)), c
