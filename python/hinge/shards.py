"""Shards of a JSON Lines file of hinges, and the work a Dask worker does on one (hinge.distributed).

A shard is a run of consecutive lines with the number of its first line; its output is produced by the
C++ code of ``hinge eval`` / ``hinge oracle`` (io::transform_hinge_lines), so that the shards' outputs
put end to end are byte for byte the command's output for the whole file, invalid lines' numbers included.
"""

from . import _hinge


def read_shards(stream, shard_lines):
    """Yields (first_line, bytes) for consecutive runs of at most shard_lines lines of a binary stream.

    Lines are split at b"\\n" only, as the command's reader splits them (std::getline)."""
    first, lines = 1, []
    for number, line in enumerate(stream, start=1):
        if not lines:
            first = number
        lines.append(line if line.endswith(b"\n") else line + b"\n")
        if len(lines) == shard_lines:
            yield first, b"".join(lines)
            lines = []
    if lines:
        yield first, b"".join(lines)


def run_shard(command, text, first_line, options):
    """The output bytes of `hinge <command>` for one shard, with the oracle's uncertified counts:
    (bytes, uncertified outputs, uncertified hinges). options: method, scalar, report_precision,
    start_bits, max_bits (keyword arguments of _hinge.stream)."""
    return _hinge.stream(command, text, first_line, **options)
