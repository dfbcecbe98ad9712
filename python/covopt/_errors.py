"""covopt's own exception: a computation that ran on valid input and did not succeed."""


class ComputationError(RuntimeError):
    """A failed computation (the library's ImpactResult status was not success).

    ``status`` is the library's status name (e.g. ``"step-limit"``); ``str(error)`` is the
    message the CLI prints for it.
    """

    def __init__(self, message, status):
        super().__init__(message)
        self.status = status
