"""Reading and writing seacable's inputs: case files (YAML) and MoorDyn input files."""

from .case_file import case_schema, dump_case, load_case, parse_case
from .moordyn import MoorDynCase, load_moordyn_case, read_moordyn

__all__ = [
           "MoorDynCase",
           "case_schema",
           "dump_case",
           "load_case",
           "load_moordyn_case",
           "parse_case",
           "read_moordyn",
]
