"""Test-suite configuration.

Under CI (the environment variable ``CI`` set, as ``.ci/run`` runs) hypothesis draws the
same examples on every run (``derandomize``), so a submission's result does not depend on
chance; a developer's local run keeps drawing new random examples, which is how new
counter-examples are found (and then written into the tests)."""
import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, database=None)
if os.environ.get("CI"):
    settings.load_profile("ci")
