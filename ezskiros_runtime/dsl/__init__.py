"""The EzSkiROS DSL: kind markers, symbolic parameters, condition expressions, tracing."""
