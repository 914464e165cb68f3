"""The tests that share a module-scoped fixture run on one pytest-xdist worker, so the
fixture is built once (tests/conftest.py's ``pytest_collection_modifyitems`` puts them in
their module's ``xdist_group``; ``--dist loadgroup`` in ``pyproject.toml``).  Nothing
fails when that grouping is lost, each worker just builds the fixture again: it was lost
twice, unseen, by the order of the hooks (xdist read the groups before tests/conftest.py
set them) and by pytest 9.2 (xdist 3.8 names the group in the test's node id, which
pytest 9.2 no longer reads: pytest-dev/pytest-xdist#1386).  xdist's scheduler groups the
tests by the ``@group`` ending of the node ids the workers report: these tests check
that ending on themselves, and that the two tests of this module ran in one process."""
import os

import pytest

_SEEN = {}


@pytest.fixture(scope="module")
def built_once():
    """A module-scoped fixture: its value records the process that built it."""
    return {"pid": os.getpid()}


def _under_loadgroup(request):
    if not os.environ.get("PYTEST_XDIST_WORKER") or not request.config.getvalue("loadgroup"):
        pytest.skip("checks the grouping of pytest-xdist's --dist loadgroup (run with -n 2)")


@pytest.mark.parametrize("k", [1, 2])
def test_a_module_fixture_s_tests_are_one_xdist_group(built_once, request, k):
    _under_loadgroup(request)
    assert request.node.get_closest_marker("xdist_group").args == ("test_xdist_groups",)
    # the name the scheduler groups by: the node id's ending after the last "]"
    assert request.node.nodeid.endswith("]@test_xdist_groups"), request.node.nodeid
    _SEEN[k] = built_once["pid"]
    assert built_once["pid"] == os.getpid()
    if len(_SEEN) == 2:                  # the second one ran where the first did
        assert _SEEN[1] == _SEEN[2]


def test_a_test_without_module_fixture_has_no_group(request):
    _under_loadgroup(request)
    assert request.node.get_closest_marker("xdist_group") is None
    assert "@" not in request.node.nodeid
