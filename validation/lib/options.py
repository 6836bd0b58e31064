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


def measured_or_stored(doc, path, measure, fine=True):
    """The data of a study that takes --stored (and --fine where fine): with --stored the JSON at path, otherwise
    measure(fine) (measure() where the study has no --fine), written to path first."""
    import json
    args = parse(doc, flags=("--fine", "--stored") if fine else ("--stored",))
    if args.get("--stored"):
        with open(path) as f:
            return json.load(f)
    data = measure(args.get("--fine", False)) if fine else measure()
    with open(path, "w") as f:
        json.dump(data, f, indent=1)
    return data
