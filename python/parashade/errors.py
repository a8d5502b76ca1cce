"""The errors parashade raises (docs/python.md): the command line's message and its exit-code category
(docs/cli.md, "Exit codes"): exit_code 2 usage, 3 bad input, 4 OpenCL or device."""


class Error(RuntimeError):
    """Any error parashade reports; exit_code is the command line's for it."""
    exit_code = 1


class UsageError(Error):
    """An option or value that cannot be read, or a PARASHADE_* variable (exit 2)."""
    exit_code = 2


class ConfigError(UsageError):
    """A combination the table of combinations refuses (`parashade combinations`; exit 2)."""


class InputError(Error):
    """A file at fault: scene, mesh, image, an output's folder; or out of host memory (exit 3)."""
    exit_code = 3


class DeviceError(Error):
    """No OpenCL platform or device, a kernel build or device failure (exit 4)."""
    exit_code = 4
