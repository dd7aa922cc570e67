"""python3 -m hinge.distributed: byte for byte `hinge oracle` / `hinge eval` on a local Dask cluster of
two worker processes (loopback), with shards small enough that invalid and blank lines fall in several."""

import os
import subprocess
import sys

import pytest


def distributed(*args):
    return subprocess.run([sys.executable, "-m", "hinge.distributed", *args], stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, env=os.environ.copy())


@pytest.fixture(scope="module")
def awkward_file(conformance_file, tmp_path_factory):
    """The conformance hinges with blank lines, invalid lines and a last line without its newline."""
    with open(conformance_file, "rb") as f:
        lines = f.read().splitlines(keepends=True)
    extra = [b"\n", b"not json\n", b'{"id": "no-x"}\n', b"   \n", b'{"id": "short", "x": [1, 2]}\n']
    mixed = []
    for i, line in enumerate(lines):
        mixed.append(line)
        if i % 41 == 0:
            mixed.append(extra[(i // 41) % len(extra)])
    mixed.append(lines[0].rstrip(b"\n"))
    path = tmp_path_factory.mktemp("distributed") / "awkward.jsonl"
    path.write_bytes(b"".join(mixed))
    return str(path)


@pytest.mark.parametrize("arguments", [["oracle"], ["eval", "--method", "fast"]])
def test_distributed_output_is_byte_for_byte_the_command(command, awkward_file, tmp_path, arguments):
    expected = command(*arguments, "--input", awkward_file)
    output = str(tmp_path / "out.jsonl")
    run = distributed(*arguments, "--input", awkward_file, "--output", output, "--local", "2", "--shard-lines", "37")
    assert run.returncode == 0, run.stderr.decode()
    with open(output, "rb") as f:
        assert f.read() == expected
    assert b'"line": ' in expected  # the invalid lines' numbers are in the comparison


def test_a_bad_hinge_isa_is_a_usage_error_found_on_the_driver(awkward_file, tmp_path):
    run = subprocess.run([sys.executable, "-m", "hinge.distributed", "eval", "--method", "fast", "--input", awkward_file,
                          "--output", str(tmp_path / "o"), "--local", "1"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         env=dict(os.environ, HINGE_ISA="sse9"))
    assert run.returncode == 2 and b"HINGE_ISA=sse9" in run.stderr


def test_usage_errors_exit_2_and_unreadable_input_exits_1(tmp_path):
    assert distributed("oracle", "--input", "x", "--output", "y").returncode == 2  # neither --local nor --scheduler
    assert distributed("eval", "--method", "newton", "--input", "x", "--output", "y", "--local", "1").returncode == 2
    assert distributed("oracle", "--input", "x", "--output", "y", "--local", "0").returncode == 2
    missing = distributed("oracle", "--input", str(tmp_path / "missing.jsonl"), "--output", str(tmp_path / "o"),
                          "--local", "1")
    assert missing.returncode == 1 and b"cannot read" in missing.stderr
    assert not os.path.exists(tmp_path / "o")
