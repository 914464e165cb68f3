"""The bundled example specs of each command (``--example NAME``): one lookup for all;
the spec file and the output folder of a report command, checked once for all."""
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


def spec_file(args, examples, what):
    """The spec file of a report command: ``SPEC.toml`` (``args.spec``) or the bundled
    example ``--example NAME`` (:func:`find_example`), one of them; ``what`` is the
    command (``"engine"``, ``"dynamics"`` …), named in the problem when neither is given."""
    from pathlib import Path

    from crankbase.errors import SpecError

    if args.spec and args.example:
        raise SpecError(Text("errors.crankdyn.give_either_spec"))
    if args.spec:
        return Path(args.spec)
    if not args.example:
        raise SpecError(Text("errors.crankdyn.give_spec", {"what": Text(f"errors.what.{what}")}))
    return find_example(args.example, examples, what)


def output_folder(args):
    """The output folder ``-o`` of a report command: a folder, or nothing yet (it is made
    when the report is written); an existing file is a problem (nothing is written)."""
    from pathlib import Path

    from crankbase.errors import SpecError

    out = Path(args.output)
    if out.exists() and not out.is_dir():
        raise SpecError(Text("errors.crankdyn.o_not_folder", {"out": out}))
    return out
