"""Reading and writing seacable's inputs: case files."""

from .case_file import case_schema, dump_case, load_case, parse_case

__all__ = ["load_case", "parse_case", "dump_case", "case_schema"]
