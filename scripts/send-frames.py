#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Replays a contact frame trace (JSON Lines, spec section 1) to a UDP port at its own pace.

The example sender for `semhap listen --udp PORT` (docs/sessions.md): each frame goes out
when its `t` comes, one JSON object per datagram, or --batch N frames as one JSON array.
Standard library only.

    scripts/send-frames.py resources/traces/demo.jsonl --port 9870
    scripts/send-frames.py trace.jsonl --port 9870 --rate 4 --batch 10
"""
import argparse
import json
import socket
import sys
import time


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("trace", help="contact frames, one JSON object per line (- for stdin)")
    parser.add_argument("--host", default="127.0.0.1", help="where semhap listens")
    parser.add_argument("--port", type=int, required=True, help="the UDP port it listens on")
    parser.add_argument("--rate", type=float, default=1.0,
                        help="speed factor: 1 real time, 2 twice as fast, 0 as fast as possible")
    parser.add_argument("--batch", type=int, default=1,
                        help="frames per datagram (more than 1: a JSON array)")
    args = parser.parse_args()
    if args.batch < 1 or args.rate < 0:
        parser.error("--batch must be at least 1 and --rate not negative")

    source = sys.stdin if args.trace == "-" else open(args.trace, encoding="utf-8")
    frames = [json.loads(line) for line in source if line.strip()]
    if not frames:
        return 0
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    target = (args.host, args.port)
    t0 = frames[0]["t"]
    start = time.monotonic()
    sent = 0
    for i in range(0, len(frames), args.batch):
        batch = frames[i:i + args.batch]
        if args.rate > 0:
            # Send a batch when its first frame is due: the receiver sees the trace's timing.
            delay = start + (batch[0]["t"] - t0) / args.rate - time.monotonic()
            if delay > 0:
                time.sleep(delay)
        payload = batch[0] if args.batch == 1 else batch
        sock.sendto(json.dumps(payload, separators=(",", ":")).encode("utf-8"), target)
        sent += len(batch)
    print(f"sent {sent} frames to udp:{args.host}:{args.port}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
