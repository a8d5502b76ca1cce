"""The study scripts moved onto the module (scripts/render_report.py: combined_study.py, phong_methods.py) read
the same reports and print the same command lines as through the command (`--binary`), timing aside."""
import os
import sys

import pytest

from conftest import BINARY, SOURCE, scene, untimed

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
from render_report import render_report  # noqa: E402

ARGS = {  # as phong_methods.render and combined_study.run make them
    "phong_methods": ["--method", "phong", "--normalize", "quadratic:cubic-fit", "--specular", "7n16", "--frames", "2",
                      "--against", "phong"],
    "combined_study": ["--method", "combined:0", "--frames", "2", "--triangle-choice", "bound", "--max-error", "16"],
}


@pytest.mark.parametrize("script", sorted(ARGS))
def test_module_and_command_give_the_same_report(tmp_path, script):
    args = ARGS[script] + ["--size", "240x135"]
    by_module, module_cmd = render_report(None, scene("sphere.json"), args, str(tmp_path), "module")
    by_command, command_cmd = render_report(BINARY, scene("sphere.json"), args, str(tmp_path), "command")
    assert module_cmd.replace("module.", "command.") == command_cmd
    assert untimed(by_module) == untimed(by_command)
    assert (tmp_path / "module.png").read_bytes() == (tmp_path / "command.png").read_bytes()
