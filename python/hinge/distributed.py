"""python3 -m hinge.distributed: hinge oracle / hinge eval on a Dask cluster (docs/scale-out.md).

    python3 -m hinge.distributed oracle --input IN.jsonl --output OUT.jsonl (--local N | --scheduler ADDRESS)
    python3 -m hinge.distributed eval --method fast --input IN.jsonl --output OUT.jsonl --local 2

The input is cut into shards of consecutive lines (--shard-lines), each certified or evaluated on a
worker by the command's own C++ code; the outputs are written in order as they arrive (at most a few
shards per worker in flight, so memory stays bounded), and OUT.jsonl appears only when complete. It is
byte for byte what ``hinge oracle`` (``hinge eval``) writes for the same input and options.
Exit status: 0 done, 1 an input or output file, or the cluster, failed, 2 usage error.
"""

import argparse
import collections
import logging
import os
import sys
import tempfile

PROGRAM = "hinge.distributed"


def parse_arguments(argv):
    parser = argparse.ArgumentParser(prog="python3 -m " + PROGRAM, description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    commands = parser.add_subparsers(dest="command", required=True, metavar="{oracle,eval}")
    for name, what in (("oracle", "certified values, as `hinge oracle`"), ("eval", "a method in a scalar type, as `hinge eval`")):
        command = commands.add_parser(name, help=what)
        command.add_argument("--input", required=True, help="input JSON Lines file of hinges")
        command.add_argument("--output", required=True, help="output JSON Lines file (written when complete)")
        where = command.add_mutually_exclusive_group(required=True)
        where.add_argument("--local", type=int, metavar="N", help="start N worker processes on this machine (loopback)")
        where.add_argument("--scheduler", metavar="ADDRESS", help="a running Dask scheduler, e.g. tcp://host:8786")
        command.add_argument("--shard-lines", type=int, default=1000, metavar="N",
                             help="input lines per shard (default 1000)")
        if name == "eval":
            command.add_argument("--method", default="reference", help="reference, fast, autodiff, symbolic")
            command.add_argument("--scalar", default="double", help="float, double, long-double, dd, qd, float128, bin128, mpfr:BITS")
        else:
            command.add_argument("--report-precision", action="store_true", help="as hinge oracle --report-precision")
            command.add_argument("--start-bits", type=int, default=128, help="as hinge oracle --start-bits")
            command.add_argument("--max-bits", type=int, default=4096, help="as hinge oracle --max-bits")
    args = parser.parse_args(argv)
    if args.local is not None and args.local < 1:
        parser.error("--local N needs N >= 1")
    if args.shard_lines < 1:
        parser.error("--shard-lines N needs N >= 1")
    if args.command == "oracle":
        for bits in ("start_bits", "max_bits"):
            if not 53 <= getattr(args, bits) <= 1 << 20:
                parser.error("--%s must be in [53, %d]" % (bits.replace("_", "-"), 1 << 20))
    return parser, args


def options_of(args):
    if args.command == "eval":
        return {"method": args.method, "scalar": args.scalar}
    return {"report_precision": args.report_precision, "start_bits": args.start_bits, "max_bits": args.max_bits}


# One valid hinge: evaluated once on the driver, so that an unknown method or scalar, or a HINGE_ISA the
# processor lacks, is a usage error (exit 2) before any cluster starts.
PROBE = b'{"id": "probe", "x": [0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 0.5]}\n'


def check_options(parser, args):
    from . import _hinge
    try:
        _hinge.stream(args.command, PROBE, 1, **options_of(args))
    except ValueError as e:
        parser.error(str(e))


def connect(args):
    from dask.distributed import Client, LocalCluster
    if args.local is not None:
        cluster = LocalCluster(n_workers=args.local, threads_per_worker=1, processes=True, host="127.0.0.1",
                               dashboard_address=None, silence_logs=logging.ERROR)
        return Client(cluster), cluster
    return Client(args.scheduler, timeout="30s"), None


def run(args, client, output):
    """Submits the shards, writes their outputs in order; returns the oracle's uncertified counts."""
    from .shards import read_shards, run_shard
    options = options_of(args)
    window = 4 * max(1, len(client.scheduler_info()["workers"]))
    pending = collections.deque()
    flagged_outputs = flagged_hinges = done = 0
    show_progress = sys.stderr.isatty()

    def write_oldest():
        nonlocal flagged_outputs, flagged_hinges, done
        text, outputs, hinges = pending.popleft().result()
        output.write(text)
        flagged_outputs += outputs
        flagged_hinges += hinges
        done += 1
        if show_progress:
            print("\r%s: %d shards written" % (PROGRAM, done), end="", file=sys.stderr, flush=True)

    with open(args.input, "rb") as stream:
        for first_line, text in read_shards(stream, args.shard_lines):
            # The shard's bytes go to a worker directly, not through the task graph (scatter).
            data = client.scatter(text, hash=False)
            pending.append(client.submit(run_shard, args.command, data, first_line, options, pure=False))
            if len(pending) >= window:
                write_oldest()
    while pending:
        write_oldest()
    if show_progress:
        print(file=sys.stderr)
    return flagged_outputs, flagged_hinges


def main(argv=None):
    parser, args = parse_arguments(argv)
    check_options(parser, args)
    if not os.access(args.input, os.R_OK) or os.path.isdir(args.input):
        print("%s: cannot read %s" % (PROGRAM, args.input), file=sys.stderr)
        return 1
    directory = os.path.dirname(os.path.abspath(args.output))
    try:
        handle, temporary = tempfile.mkstemp(dir=directory, prefix=os.path.basename(args.output) + ".", suffix=".partial")
    except OSError as e:
        print("%s: cannot write %s: %s" % (PROGRAM, args.output, e.strerror), file=sys.stderr)
        return 1
    output = os.fdopen(handle, "wb")
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(temporary, 0o666 & ~umask)  # as any file the command writes, not mkstemp's 0600
    cluster = client = None
    try:
        client, cluster = connect(args)
        with output:
            flagged_outputs, flagged_hinges = run(args, client, output)
        os.replace(temporary, args.output)
    except Exception as e:  # noqa: BLE001: the cluster, a worker or a file failed: exit 1 with its message
        output.close()
        print("%s: %s: %s" % (PROGRAM, type(e).__name__, e), file=sys.stderr)
        return 1
    finally:
        if os.path.exists(temporary):
            os.unlink(temporary)
        if client is not None:
            client.close()
        if cluster is not None:
            cluster.close()
    if flagged_outputs:
        print("hinge oracle: %d output(s) in %d hinge(s) could not be certified within %d bits; they are flagged "
              "\"uncertified\" with their enclosures" % (flagged_outputs, flagged_hinges, args.max_bits), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
