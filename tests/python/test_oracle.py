"""hinge.oracle: bit for bit `hinge oracle`."""

import hinge
from conftest import read_results, read_x
from test_eval import assert_same_as_command


def test_oracle_is_bit_for_bit_the_command(command, conformance_file):
    lines = read_results(command("oracle", "--input", conformance_file))
    result = hinge.oracle(read_x(conformance_file))
    assert_same_as_command(result, lines)
    assert result.uncertified == [None] * len(lines)
