"""Command-line options of the validation scripts that take a few flags by hand:
-h/--help prints the script's docstring, and an unknown option stops the script
before it starts runs that can take an hour."""
import sys


def parse(doc, flags=(), valued=()):
    """sys.argv[1:] checked against flags (no value) and valued options (one value
    each); returns {option: True or its value} for those given."""
    args = sys.argv[1:]
    if "-h" in args or "--help" in args:
        print(doc)
        sys.exit(0)
    given, k = {}, 0
    while k < len(args):
        a = args[k]
        if a in flags:
            given[a] = True
        elif a in valued and k + 1 < len(args):
            given[a] = args[k + 1]
            k += 1
        else:
            sys.exit("%s: %s '%s'; usage:\n%s" % (sys.argv[0], "no value for" if a in valued else "unknown option",
                                                  a, doc))
        k += 1
    return given
