#!/usr/bin/env python3
"""An ssh ProxyCommand that is a slow link: relays stdin/stdout to HOST:PORT,
each direction at RATE bits a second (bytes leave in order, in pieces of
1 KB) and DELAY milliseconds later. What waits before the link is bounded
(QUEUE_LIMIT): past it the relay stops reading, and the sender's own buffers
(sshd's TCP send buffer) fill, as on a real slow link. Loopback only.

Usage: throttle_relay.py RATE_BITS DELAY_MS HOST PORT
  ssh -o ProxyCommand='throttle_relay.py 256000 50 127.0.0.1 %p' ...
"""
import collections
import os
import socket
import sys
import threading
import time

PIECE_BYTES = 1024
QUEUE_LIMIT = 256 * 1024


class Direction:
    """One way of the link: read from `read`, write to `write` later."""

    def __init__(self, read, write, done, rate_bits, delay_s):
        self.read, self.write, self.done = read, write, done
        self.bytes_per_s = rate_bits / 8.0
        self.delay_s = delay_s
        self.queue = collections.deque()  # (arrival time, bytes)
        self.queued = 0
        self.eof = False
        self.cv = threading.Condition()

    def reader(self):
        free_at = 0.0
        while True:
            with self.cv:
                while self.queued >= QUEUE_LIMIT:
                    self.cv.wait()
            data = self.read()
            now = time.monotonic()
            with self.cv:
                if not data:
                    self.eof = True
                    self.cv.notify_all()
                    return
                for at in range(0, len(data), PIECE_BYTES):
                    piece = data[at:at + PIECE_BYTES]
                    free_at = max(now, free_at) + len(piece) / self.bytes_per_s
                    self.queue.append((free_at + self.delay_s, piece))
                    self.queued += len(piece)
                self.cv.notify_all()

    def writer(self):
        while True:
            with self.cv:
                while not self.queue and not self.eof:
                    self.cv.wait()
                if not self.queue:
                    break
                arrival, piece = self.queue[0]
            wait = arrival - time.monotonic()
            if wait > 0:
                time.sleep(wait)
                continue
            try:
                self.write(piece)
            except OSError:
                break
            with self.cv:
                self.queue.popleft()
                self.queued -= len(piece)
                self.cv.notify_all()
        self.done()


def write_all(fd, data):
    while data:
        data = data[os.write(fd, data):]


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    rate_bits, delay_s = float(sys.argv[1]), float(sys.argv[2]) / 1000.0
    host, port = sys.argv[3], int(sys.argv[4])
    if host not in ("127.0.0.1", "localhost", "::1"):
        sys.exit("throttle_relay.py: loopback only")
    sock = socket.create_connection((host, port))
    sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    stdin, stdout = sys.stdin.fileno(), sys.stdout.fileno()
    up = Direction(lambda: os.read(stdin, 65536), sock.sendall,
                   lambda: sock.shutdown(socket.SHUT_WR), rate_bits, delay_s)
    down = Direction(lambda: sock.recv(65536), lambda data: write_all(stdout, data),
                     lambda: os.close(stdout), rate_bits, delay_s)
    threads = [threading.Thread(target=f, daemon=True)
               for d in (up, down) for f in (d.reader, d.writer)]
    for thread in threads:
        thread.start()
    threads[3].join()  # everything from the server has been passed on


if __name__ == "__main__":
    main()
