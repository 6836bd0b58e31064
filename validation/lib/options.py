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


def name_key(name):
    """A study's or scene's name as a --studies/--cases word matches it: lower case, no spaces or commas."""
    return name.lower().replace(" ", "").replace(",", "")


def chosen_names(value, names, option):
    """The words of an option such as --studies (comma-separated, matched against name_key of each name), or None
    where the option was not given; stops the script where the words name none of names."""
    if not value:
        return None
    words = [name_key(w) for w in value.split(",")]
    if not any(w in name_key(n) for w in words for n in names):
        sys.exit("%s: %s names none of %s" % (option, value, "; ".join(names)))
    return words


def is_chosen(name, words):
    """Whether a study or scene is among those chosen_names() returned (all where None)."""
    return words is None or any(w in name_key(name) for w in words)
