"""meshio for the interop tests, or the skip: Debian's python3-meshio lives with Debian's
interpreter, and a python3 from another installation first on PATH (pyenv, venv) cannot see
it, so the script is handed over to the system interpreter once before it gives up (exit
77, meson's skip)."""
import os
import sys


def require_meshio():
    try:
        import meshio
        return meshio
    except ImportError:
        system_python = "/usr/bin/python3"
        if os.path.realpath(sys.executable) != os.path.realpath(system_python) \
                and os.path.exists(system_python) and not os.environ.get("TETREC_REEXEC"):
            os.environ["TETREC_REEXEC"] = "1"
            os.execv(system_python, [system_python] + sys.argv)
        print("meshio not installed: skipped")
        sys.exit(77)
