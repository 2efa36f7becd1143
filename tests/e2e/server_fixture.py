"""Starts the real swarmplan-server for an end-to-end test and stops it afterwards.

The server listens on 127.0.0.1 with a port it picks itself (--listen 127.0.0.1:0; the port is
read from its log line "listening on port N"), keeps its embedded store in a temporary data
directory, and has the metrics endpoint off. Standard library only.
"""

import os
import re
import shutil
import signal
import subprocess
import tempfile
import time


class ServerFixture:
    def __init__(self, server_binary, extra_args=()):
        self.server_binary = server_binary
        self.extra_args = list(extra_args)
        self.workdir = None
        self.process = None
        self.port = None
        self.log_path = None

    @property
    def address(self):
        return "127.0.0.1:%d" % self.port

    def start(self, timeout=60.0):
        self.workdir = tempfile.mkdtemp(prefix="swarmplan-e2e-")
        data_dir = os.path.join(self.workdir, "data")
        self.log_path = os.path.join(self.workdir, "server.log")
        log = open(self.log_path, "wb")
        self.process = subprocess.Popen(
            [self.server_binary, "--listen", "127.0.0.1:0", "--data-dir", data_dir,
             "--metrics-port", "0", "--workers", "2"] + self.extra_args,
            stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
        log.close()
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            match = re.search(r"listening on port (\d+)", self.log())
            if match:
                self.port = int(match.group(1))
                return self
            if self.process.poll() is not None:
                raise RuntimeError("swarmplan-server exited with %s before listening:\n%s"
                                   % (self.process.returncode, self.log()))
            time.sleep(0.05)
        self.stop()
        raise RuntimeError("swarmplan-server did not report its port within %.0fs:\n%s"
                           % (timeout, self.log()))

    def log(self):
        try:
            with open(self.log_path, "r", errors="replace") as f:
                return f.read()
        except OSError:
            return ""

    def stop(self):
        if self.process is not None and self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self.process = None
        if self.workdir:
            shutil.rmtree(self.workdir, ignore_errors=True)
            self.workdir = None

    def __enter__(self):
        return self.start()

    def __exit__(self, *exc):
        self.stop()
        return False
