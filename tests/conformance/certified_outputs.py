"""The certified outputs of the conformance inputs, as `hinge oracle` writes them (the scripts of this folder
build their candidates from them)."""
import json
import os
import subprocess


def certified_outputs(hinge, work):
    """Runs hinge conform --inputs and hinge oracle once into `work`; the output lines as dicts."""
    inputs, certified = os.path.join(work, "inputs.jsonl"), os.path.join(work, "oracle.jsonl")
    if not os.path.exists(certified):
        subprocess.run([hinge, "conform", "--inputs", "--output", inputs], check=True)
        subprocess.run([hinge, "oracle", "--input", inputs, "--output", certified], check=True)
    return [json.loads(line) for line in open(certified)]
