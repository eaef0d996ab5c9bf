# SPDX-License-Identifier: MIT
"""Test support for `hula serve`: start the real server on a free loopback
port, talk to it with Python's http.client, parse Server-Sent Events and
validate every JSON body against the server's own OpenAPI document.

Shared by server_test.py (ctest, label `server`) and bench/server/server_load.py.
"""
import http.client
import json
import os
import re
import signal
import subprocess
import tempfile
import time

import jsonschema


class Server:
    """A running `hula serve`; use as a context manager (stops it on exit)."""

    def __init__(self, hula, workspace=None, args=(), token_file=None):
        self.hula = hula
        self._tmp = None
        if workspace is None:
            self._tmp = tempfile.TemporaryDirectory(prefix="hula-serve-")
            workspace = self._tmp.name
        self.workspace = workspace
        self.stderr_path = os.path.join(tempfile.gettempdir(), f"hula-serve-{os.getpid()}-{id(self)}.log")
        command = [hula, "serve", "--workspace", workspace, "--port", "0", *args]
        if token_file:
            command += ["--token-file", token_file]
        self._stderr = open(self.stderr_path, "w+b")
        self.process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=self._stderr)
        line = self.process.stdout.readline()
        if not line:
            self.process.wait(10)
            raise RuntimeError("hula serve did not start: " + self.log_text())
        self.start_line = line.decode()
        self.info = json.loads(self.start_line)
        self.port = self.info["port"]
        self.token = self.info["token"]

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stop()

    def stop(self, sig=signal.SIGTERM, timeout=30):
        """Sends `sig` and returns the exit code."""
        if self.process.poll() is None:
            self.process.send_signal(sig)
            try:
                self.process.wait(timeout)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self.process.stdout.close()
        self._stderr.close()
        if self._tmp is not None:
            self._tmp.cleanup()
            self._tmp = None
        return self.process.returncode

    def log_text(self):
        with open(self.stderr_path, "rb") as f:
            return f.read().decode(errors="replace")

    def connection(self, timeout=30):
        return http.client.HTTPConnection("127.0.0.1", self.port, timeout=timeout)

    def request(self, method, path, body=None, token=True, headers=None, conn=None, raw_body=None):
        """One request; returns (status, headers dict, body bytes)."""
        h = {}
        if token is True:
            h["Authorization"] = "Bearer " + self.token
        elif isinstance(token, str):
            h["Authorization"] = "Bearer " + token
        if body is not None:
            raw_body = json.dumps(body).encode()
        if raw_body is not None:
            h["Content-Type"] = "application/json"
        h.update(headers or {})
        own = conn is None
        c = conn or self.connection()
        try:
            c.request(method, path, body=raw_body, headers=h)
            r = c.getresponse()
            data = r.read()
            return r.status, {k.lower(): v for k, v in r.getheaders()}, data
        finally:
            if own:
                c.close()


def read_events(response):
    """Yields (event, data) pairs from an http.client response of text/event-stream."""
    event, data = None, []
    while True:
        line = response.fp.readline()
        if not line:
            return
        line = line.decode().rstrip("\r\n")
        if line == "":
            if event is not None or data:
                yield event, json.loads("\n".join(data))
            event, data = None, []
        elif line.startswith("event:"):
            event = line[6:].strip()
        elif line.startswith("data:"):
            data.append(line[5:].lstrip())


def open_events(server, path, token=True):
    """Opens an SSE stream; returns (connection, response)."""
    c = server.connection(timeout=120)
    h = {"Accept": "text/event-stream"}
    if token:
        h["Authorization"] = "Bearer " + server.token
    c.request("GET", path, headers=h)
    return c, c.getresponse()


class OpenApi:
    """The server's OpenAPI document; checks response bodies against it."""

    def __init__(self, document):
        self.document = document
        self.seen = set()

    def _inline(self, schema, depth=0):
        # Replaces local $refs by their targets (the document has no recursive schemas), so any
        # jsonschema version validates it without a resolver.
        if depth > 32:
            raise ValueError("recursive $ref in the OpenAPI document")
        if isinstance(schema, dict):
            if "$ref" in schema:
                target = self.document
                for part in schema["$ref"].lstrip("#/").split("/"):
                    target = target[part]
                return self._inline(target, depth + 1)
            return {k: self._inline(v, depth + 1) for k, v in schema.items()}
        if isinstance(schema, list):
            return [self._inline(v, depth + 1) for v in schema]
        return schema

    def operation(self, method, path):
        """(template, operation) for a concrete path."""
        path = path.split("?")[0]
        for template, item in self.document["paths"].items():
            pattern = "^" + re.sub(r"\{[^}]+\}", "[^/]+", template) + "$"
            if re.match(pattern, path) and method.lower() in item:
                return template, item[method.lower()]
        raise AssertionError(f"{method} {path} is not in the OpenAPI document")

    def schema(self, name):
        return self._inline({"$ref": "#/components/schemas/" + name})

    def validate(self, method, path, status, body, content_type="application/json"):
        """Validates a response body against the documented schema of (method, path, status)."""
        template, op = self.operation(method, path)
        responses = op["responses"]
        key = str(status)
        if key not in responses:
            raise AssertionError(f"{method} {template} answered {status}, which the OpenAPI document does not list")
        content = responses[key].get("content", {})
        media = content_type.split(";")[0].strip()
        if media not in content:
            raise AssertionError(f"{method} {template} {status}: content type {media} not documented")
        self.seen.add((template, method.lower(), key))
        if media == "application/json":
            jsonschema.Draft202012Validator(self._inline(content[media]["schema"])).validate(json.loads(body))

    def validate_events(self, path, response, events, schemas):
        """Validates an SSE stream of GET `path`: its status and content type against the document, and each
        event's data against the component schema named by schemas[event name] (an unnamed event fails)."""
        self.validate("GET", path, response.status, "", response.getheader("Content-Type", ""))
        for name, data in events:
            if name not in schemas:
                raise AssertionError(f"GET {path}: event '{name}' is not one the OpenAPI document describes")
            jsonschema.Draft202012Validator(self.schema(schemas[name])).validate(data)

    def validate_error_body(self, body):
        """Errors outside the route table (404, 405, 414, 431, 503 ...) share one schema."""
        jsonschema.Draft202012Validator(self.schema("Error")).validate(json.loads(body))


def wait_until(predicate, timeout, step=0.02):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(step)
    return predicate()
