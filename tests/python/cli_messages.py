"""How the module words the CLI's one-line messages: the Python keyword where the CLI names its
option ("--p-c: …" is "p_c: …", "--start: …" is "starts: …"), without the CLI's "(see --help)"."""

import re


def python_message(cli_message, keyword=None):
    """The CLI's message as the module raises it; `keyword` replaces the option's own name when
    the Python argument is called differently (run_experiment's config for --preset)."""
    message = cli_message.removesuffix(" (see --help)")

    def name(match):
        if keyword is not None:
            return keyword
        return "starts" if match.group(1) == "start" else match.group(1).replace("-", "_")

    return re.sub(r"^--([a-z0-9-]+)", name, message)
