"""gaphys_gen: geometric-algebra specs in, specialized C++ libraries out.

Stages, one module each: lexer -> parser (syntax tree) -> model (validated
algebra) -> blades (exact product tables) -> symbolic / expand (kernels)
-> render (Jinja2) -> output (atomic write).
"""

VERSION = "0.1.0"
