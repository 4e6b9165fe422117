"""The codemod's machinery: IR, name resolution, rule registry, replay, writing code."""
