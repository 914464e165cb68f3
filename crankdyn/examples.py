"""The bundled example specs of each command (``--example NAME``): one lookup for all."""
from __future__ import annotations
from crankbase.errors import Text


def find_example(name, examples, what):
    """The path of the bundled example ``name`` of a command: a short name of ``examples``
    (``{short name: file name}``) or the file's stem, with or without ``.toml``; any other
    name (an example of another command among them) is a :class:`SpecError` naming the
    command's own examples."""
    from crankbase.errors import SpecError
    from crankbase.resources import example_path

    stems = {f[:-5]: f for f in examples.values()}
    stem = name[:-5] if name.endswith(".toml") else name
    fname = examples.get(stem) or stems.get(stem)
    if fname is None:
        raise SpecError(
                        Text("errors.crankdyn.examples.example_no_example",
                             {"what": Text(f"errors.what.{what}"), "name": name,
                              "items": ", ".join(list(examples)
                                                 + [s for s in stems if s not in examples])}))
    return example_path(fname)
