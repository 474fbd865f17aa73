"""Validates a JUnit XML report against tests/grading/junit.xsd.

usage: python validate_junit.py SCHEMA REPORT
Exit 0 and 'valid' when it is; exit 1 with the reason otherwise. Needs
xmlschema (tests/jupyter/requirements.txt, installed by .ci/run).
"""
import sys

import xmlschema

schema = xmlschema.XMLSchema(sys.argv[1])
try:
    schema.validate(sys.argv[2])
except xmlschema.XMLSchemaValidationError as e:
    print(f"invalid: {e}", file=sys.stderr)
    sys.exit(1)
print("valid")
