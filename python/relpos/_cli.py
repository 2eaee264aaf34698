"""Where the relpos command-line tool is: the one lookup, for the tests and benchmarks that compare the
package with `relpos batch` (the package itself, relpos.distributed included, answers in-process
through its extension and never runs the CLI)."""

import os
import shutil
import sysconfig

from . import _build


def find_cli():
    """Path of the `relpos` executable.

    In order: the environment variable RELPOS_CLI; `<prefix>/bin/relpos` when this package is
    installed under `<prefix>/lib/python3/dist-packages/relpos` (cmake --install) or
    `<venv>/lib/python3.X/site-packages/relpos` (pip); the scripts directory of the running
    interpreter (pip puts the CLI there); the CLI of the build tree that built this package;
    `relpos` on PATH. Raises FileNotFoundError naming what was tried.
    """
    tried = []
    env = os.environ.get("RELPOS_CLI")
    if env:
        if os.path.isfile(env) and os.access(env, os.X_OK):
            return env
        raise FileNotFoundError("RELPOS_CLI=%s is not an executable file" % env)
    here = os.path.dirname(os.path.abspath(__file__))
    candidates = [
        os.path.normpath(os.path.join(here, "..", "..", "..", "..", "bin", "relpos")),
        os.path.join(sysconfig.get_path("scripts"), "relpos"),
    ]
    if _build.build_tree_cli:
        candidates.append(_build.build_tree_cli)
    for c in candidates:
        tried.append(c)
        if os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    on_path = shutil.which("relpos")
    if on_path:
        return on_path
    raise FileNotFoundError(
        "relpos CLI not found (set RELPOS_CLI); tried %s and PATH" % ", ".join(tried)
    )
