"""The Python side of the bench scenario `python` (bench/bench_python.c), which embeds the
interpreter and times these calls next to the C API's in the same process.

MiuraFold(n).fold(): the 100 × 100 Miura fold of bench_miura.c through the binding, 5° → 175° in
100 output steps from the 5° state, every frame kept and read through the view motion.angles.
design_steps(seconds): DesignEnv steps on a 4 × 4 sheet with random creases through its grid
points; returns (steps, wall seconds, CPU seconds, wall seconds inside the library's design step).
"""

import math
import random
import time

import orikin
import orikin.design


class MiuraFold:
    def __init__(self, n: int):
        self.p = orikin.generate("miura", rows=n, cols=n, width=1.0, height=math.sqrt(1.25),
                                 angle=math.degrees(math.atan2(1.0, 0.5)))
        v = self.p.vertices
        i = j = n // 2
        a, b = j * (n + 1) + i, (j + 1) * (n + 1) + i  # the middle zig-zag crease, as bench_miura.c
        self.drive = self.p.edge(((v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2))
        self.sign = 1.0 if self.p.assignment[self.drive] == "V" else -1.0
        first = self.p.fold(fix=0, drive=self.drive, to=self.sign * 5.0, step=5.0, collisions=False)
        self.start = first.frame(-1)

    def edge_vertices(self):
        return [int(x) for x in self.p.edges[self.drive]]

    def fold(self):
        m = self.p.fold(fix=0, drive=self.drive, to=self.sign * 175.0, step=1.7, start=self.start, collisions=False)
        a = m.angles  # the library's frames, viewed
        return m.frame_count, float(a[-1, self.drive]), float(m.residuals.max())


class _Timed:
    """orikin.design's view of the extension with design_step timed."""

    def __init__(self, c):
        self._c, self.seconds = c, 0.0

    def design_step(self, *args):
        t0 = time.perf_counter()
        r = self._c.design_step(*args)
        self.seconds += time.perf_counter() - t0
        return r

    def __getattr__(self, name):
        return getattr(self._c, name)


def design_steps(seconds: float, seed: int = 1, max_creases: int = 6):
    env = orikin.DesignEnv(orikin.Pattern.square(4))
    rng = random.Random(seed)
    pts = [(float(x), float(y)) for x in range(5) for y in range(5)]
    timed = _Timed(orikin.design._c)
    orikin.design._c = timed
    steps, t0, c0 = 0, time.perf_counter(), time.process_time()
    try:
        while time.perf_counter() - t0 < seconds:
            a, b = rng.sample(pts, 2)
            if (a[0] == b[0] and a[0] in (0.0, 4.0)) or (a[1] == b[1] and a[1] in (0.0, 4.0)):
                continue  # along the boundary: no crease
            r = env.step({"line": (a, b), "assignment": rng.choice("MV")})
            steps += 1
            if r.terminated or len(env.history) >= max_creases:
                env.reset()
    finally:
        orikin.design._c = timed._c
    return steps, time.perf_counter() - t0, time.process_time() - c0, timed.seconds
