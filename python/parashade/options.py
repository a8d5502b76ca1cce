"""Keyword arguments as the command line's words (docs/python.md): `name=value` is `--name value` with
underscores for the inner dashes (max_error=4 is --max-error 4), True is a flag given, False and None leave the
option out, a list or tuple gives the option once per item, size=(W, H) is --size WxH and a dict (tune's params)
gives NAME=V1,V2 per key. The command parses the words: its names, defaults and messages hold."""


def option_words(options):
    words = []
    for name, value in options.items():
        flag = ("-" if len(name) == 1 else "--") + name.replace("_", "-")
        if value is None or value is False:
            continue
        if value is True:
            words.append(flag)
        elif name == "size" and isinstance(value, (list, tuple)):
            words += [flag, "%dx%d" % tuple(value)]
        elif isinstance(value, dict):
            for key, values in value.items():
                items = values if isinstance(values, (list, tuple)) else [values]
                words += [flag, "%s=%s" % (key, ",".join(str(v) for v in items))]
        elif isinstance(value, (list, tuple)):
            for item in value:
                words += [flag, str(item)]
        else:
            words += [flag, str(value)]
    return words
