"""The `safegate` command's sub-commands, one module per group (keys, templates, the quick gate).

`app.cli` assembles them; each module's docstring says what goes in and out.
"""
