"""Code generation: the language-independent Program, and its Python, array, C and
looped-C printers."""
