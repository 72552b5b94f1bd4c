#!/usr/bin/env python3
"""Serves a folder on 127.0.0.1 (files only), for the live page: scripts/web.sh serves web/,
scripts/web-test.sh the repository. Every answer allows any origin
(Access-Control-Allow-Origin: *), so that a page `fixstep render REPLAY --html PAGE.html`
wrote, opened from anywhere (a file:// page too), can load the player's modules and wasm.
Usage: scripts/web-serve.py PORT FOLDER"""
import functools
import http.server
import sys


class Handler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map,
                      ".wasm": "application/wasm", ".js": "text/javascript",
                      ".mjs": "text/javascript"}

    def end_headers(self):
        self.send_header("Access-Control-Allow-Origin", "*")
        super().end_headers()


def main():
    if len(sys.argv) != 3 or not sys.argv[1].isdigit():
        print("usage: web-serve.py PORT FOLDER", file=sys.stderr)
        sys.exit(2)
    handler = functools.partial(Handler, directory=sys.argv[2])
    server = http.server.ThreadingHTTPServer(("127.0.0.1", int(sys.argv[1])), handler)
    server.serve_forever()


if __name__ == "__main__":
    main()
