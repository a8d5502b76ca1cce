"""The "schema" field of the JSON files the scripts write (docs/reports.md): "parashade.<kind>/<version>", the
version shared with the parashade command's reports (report_header.hpp's kReportVersion), raised for every
kind at once when a key is renamed, removed or changes meaning. schemas/<kind>.schema.json describes each."""

VERSION = 2


def schema(kind):
    """The schema field of a file of this kind: schema("memory") == "parashade.memory/2"."""
    return "parashade.%s/%d" % (kind, VERSION)
