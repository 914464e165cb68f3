"""crankbase: the small base under every crankdyn package.

Imports nothing of the project and nothing heavy: typed errors (:mod:`.errors`), spec
validation (:mod:`.validation`), safe output of reports (:mod:`.output`), shipped files
(:mod:`.resources`) and the named numerical tolerances (:mod:`.tolerances`).  The flow is
one way: ``crankbase`` → ``linkage`` → ``engine`` and the other calculation packages →
their reports and plots → the ``crankdyn`` command line.
"""
