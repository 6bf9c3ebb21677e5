# SPDX-License-Identifier: BSD-2-Clause
"""The OpenAPI 3.0 document of the service, built from the function table
so that it cannot drift from what /v1/eval accepts. python/openapi.json
is this document with the default limits (`python -m drdc.serve
--openapi > python/openapi.json` writes it; a test compares)."""
from .functions import EXAMPLES, FUNCTIONS, RANGES, quantity


def _error():
    return {"description": "refused: the reason as JSON",
            "content": {"application/json": {
                "schema": {"$ref": "#/components/schemas/Error"}}}}


def _integer(ctype):
    lo, hi = RANGES[ctype]
    if ctype == "bool":
        return {"oneOf": [{"type": "integer", "minimum": 0, "maximum": 1},
                          {"type": "boolean"}]}
    return {"type": "integer", "minimum": lo, "maximum": hi}


def _input_schema(arg, batch):
    if arg.kind == "text":
        one = {"type": "string", "maxLength": 64}
    elif arg.kind == "scalar-text":
        return {"type": "string", "maxLength": 64,
                "description": arg.format}
    elif arg.kind == "scalar-int":
        return dict(_integer(arg.ctype), description=arg.format)
    else:
        one = _integer(arg.ctype)
        q = quantity(arg)
        if q is not None:
            # the quantity a person types, converted exactly
            one = {"oneOf": [one, {
                "type": "object", "additionalProperties": False,
                "required": [q[0]],
                "properties": {q[0]: {"type": "string", "maxLength": 64,
                                      "description": q[1]}}}]}
    return {"description": arg.format + " (one value for every element, "
            "or a list)",
            "oneOf": [one, {"type": "array", "items": one,
                            "maxItems": batch}]}


def _eval_request(f, batch):
    return {
        "type": "object",
        "additionalProperties": False,
        "required": ["function", "inputs"],
        "properties": {
            "function": {"type": "string", "enum": [f.name]},
            "inputs": {
                "type": "object",
                "additionalProperties": False,
                "required": [a.name for a in f.inputs if a.default is None],
                "properties": {a.name: _input_schema(a, batch)
                               for a in f.inputs},
            },
        },
        "example": {"function": f.name, "inputs": EXAMPLES[f.name]},
    }


def document(limits):
    batch = limits.batch
    errors = {str(c): _error() for c in (400, 404, 413, 415, 422, 429, 503)}
    return {
        "openapi": "3.0.3",
        "info": {
            "title": "libdrdc-fx gold-standard service",
            "version": "1",
            "description": (
                "The library's exact integers over HTTP: every function's "
                "formats and accuracy, batches of inputs evaluated bit for "
                "bit as the firmware computes them, and the conformance "
                "verdict of a test-runner console log. Limits: a body of "
                "at most %d bytes, %d elements a request, %g requests a "
                "second per client (bursts of %g), %g s a request."
                % (limits.body_bytes, batch, limits.rate, limits.burst,
                   limits.timeout)),
        },
        "paths": {
            "/": {"get": {
                "summary": "the one-page front end",
                "responses": {"200": {"description": "HTML",
                                      "content": {"text/html": {
                                          "schema": {"type": "string"}}}},
                              "429": _error()}}},
            "/openapi.json": {"get": {
                "summary": "this document",
                "responses": {"200": {"description": "OpenAPI 3.0",
                                      "content": {"application/json": {
                                          "schema": {"type": "object"}}}},
                              "429": _error()}}},
            "/v1/functions": {"get": {
                "summary": "every function: inputs and outputs with their "
                           "fixed-point formats, accuracy and header",
                "responses": {"200": {"description": "the table",
                                      "content": {"application/json": {
                                          "schema": {"$ref": "#/components"
                                                     "/schemas/Functions"}}}},
                              "429": _error()}}},
            "/v1/eval": {"post": {
                "summary": "a function over a batch of inputs, bit-exact",
                "requestBody": {"required": True, "content": {
                    "application/json": {"schema": {
                        "$ref": "#/components/schemas/EvalRequest"}}}},
                "responses": dict({"200": {
                    "description": "outputs and a status per element",
                    "content": {"application/json": {"schema": {
                        "$ref": "#/components/schemas/EvalResult"}}}}},
                    **errors)}},
            "/v1/conformance": {"post": {
                "summary": "a test-runner console log -> the conformance "
                           "verdict",
                "requestBody": {"required": True, "content": {
                    "text/plain": {"schema": {"type": "string"}},
                    "application/json": {"schema": {
                        "type": "object", "additionalProperties": False,
                        "required": ["log"],
                        "properties": {"log": {"type": "string"}}}}}},
                "responses": dict({"200": {
                    "description": "judge()'s answer",
                    "content": {"application/json": {"schema": {
                        "$ref": "#/components/schemas/Verdict"}}}}},
                    **errors)}},
        },
        "components": {"schemas": {
            "Error": {"type": "object", "required": ["error"],
                      "properties": {"error": {
                          "type": "object", "required": ["status", "reason"],
                          "properties": {
                              "status": {"type": "integer"},
                              "reason": {"type": "string"}}}}},
            "EvalRequest": {"oneOf": [
                {"$ref": "#/components/schemas/Eval_" + f.name}
                for f in FUNCTIONS]},
            **{"Eval_" + f.name: _eval_request(f, batch)
               for f in FUNCTIONS},
            "EvalResult": {
                "type": "object",
                "required": ["function", "count", "outputs", "status",
                             "status_name", "display", "exact"],
                "properties": {
                    "function": {"type": "string"},
                    "count": {"type": "integer"},
                    "outputs": {"type": "object",
                                "additionalProperties": {"type": "array"}},
                    "status": {"type": "array",
                               "items": {"type": "integer"}},
                    "status_name": {"type": "array",
                                    "items": {"type": "string"}},
                    "display": {
                        "type": "object",
                        "description": "outputs that are quantities, as "
                                       "exact decimal text with their unit "
                                       "(null where the status is an "
                                       "error)",
                        "additionalProperties": {"type": "array"}},
                    "exact": {
                        "type": "object",
                        "description": "every integer output as decimal "
                                       "text (for clients whose numbers "
                                       "are doubles)",
                        "additionalProperties": {
                            "type": "array", "items": {"type": "string"}}}}},
            "Functions": {
                "type": "object", "required": ["functions"],
                "properties": {"functions": {
                    "type": "array", "items": {"type": "object"}}}},
            "Verdict": {
                "type": "object",
                "required": ["verdict", "digest", "modules"],
                "properties": {
                    "verdict": {"type": "string", "enum": [
                        "conforms", "differs", "incomplete"]},
                    "digest": {"type": "object"},
                    "modules": {"type": "array",
                                "items": {"type": "object"}}}},
        }},
    }
