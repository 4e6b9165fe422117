"""Recording stand-in for ``skiros2_common.core``."""
