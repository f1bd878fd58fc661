#!/usr/bin/env python3
"""The same landings through the peers' *documented* ground models (docs/ground.md).

Not the peers' code: their published equations, as their docs state them, evaluated on
the landing states carry computes for the TrackMan tour driver and pitching wedge.

- gc2-connect-desktop docs/PHYSICS.md §8: v_n' = -COR v_n, v_t' = v_t (1 - 0.3 friction),
  spin x0.7 per bounce (no spin term in the velocity), roll deceleration
  max(RollingResistance g, 0.5 m/s^2), stopped below 0.1 m/s, at most 5 bounces.
  Fairway COR 0.60, RR 0.10, friction 0.50; green 0.40, 0.05, 0.30; rough 0.30, 0.30, 0.70.
- libgolf docs/bounce_model.md and roll_model.md (DefaultBounceModel, DefaultRollModel):
  v_n' = -COR v_n, v_t' = f v_t with f = 1 - mu_s (1 - firmness), then
  v_t' *= max(0, 1 - (2 r |w| / 7) / |v_t'|), w' = retention w; roll a = mu_d g, stop
  below 0.1 ft/s. GroundSurface defaults (fairway): COR 0.4, mu_s 0.5, mu_d 0.2,
  firmness 0.8, retention 0.75.

Both: hops in vacuum; bouncing ends when a rebound would rise less than 5 mm (Penner's
criterion; neither document states its own), then the ball rolls.
Usage: python3 bench/ground_peers.py
"""
import math

G = 9.80665
R = 0.021335
YD = 0.9144
STOP_H = 0.005

# carry's landing states (f64, default fidelity): speed m/s, angle below horizontal deg,
# backspin rpm — from `carry flight --json` with the TrackMan PGA Tour 2023 launches.
LANDINGS = {
    "tour driver": (28.92, 38.5, 1857.0),
    "tour pitching wedge": (19.50, 53.2, 8060.0),
}


def run(v, angle_deg, spin_rpm, bounce, decel, max_bounces=1000, stop_v=0.0):
    a = math.radians(angle_deg)
    u, vn, w = v * math.cos(a), v * math.sin(a), spin_rpm * math.tau / 60.0
    x = 0.0
    for _ in range(max_bounces):
        u, up, w = bounce(u, vn, w)
        if up * up < 2 * G * STOP_H:
            break
        t = 2 * up / G
        x += u * t
        vn = up
    if abs(u) > stop_v and decel > 0:
        x += math.copysign(u * u / (2 * decel), u)
    return x


def gc2(surface):
    cor, rr, fr = surface

    def bounce(u, vn, w):
        return u * (1 - fr * 0.3), cor * vn, w * 0.7

    return bounce, max(rr * G, 0.5)


def libgolf(cor=0.4, mu_s=0.5, mu_d=0.2, firm=0.8, ret=0.75):
    f = min(max(1 - mu_s * (1 - firm), 0.0), 1.0)

    def bounce(u, vn, w):
        ut = f * u
        spin_t = 2 * R * abs(w) / 7
        if abs(ut) > 0:
            ut *= max(0.0, 1 - spin_t / abs(ut))
        return ut, cor * vn, ret * w

    return bounce, mu_d * G


if __name__ == "__main__":
    surfaces = {
        "gc2 fairway": gc2((0.60, 0.10, 0.50)),
        "gc2 green": gc2((0.40, 0.05, 0.30)),
        "gc2 rough": gc2((0.30, 0.30, 0.70)),
        "libgolf default (fairway)": libgolf(),
    }
    for shot, (v, a, s) in LANDINGS.items():
        for name, (bounce, decel) in surfaces.items():
            mb = 5 if name.startswith("gc2") else 1000
            stop = 0.1 if name.startswith("gc2") else 0.1 * 0.3048
            x = run(v, a, s, bounce, decel, mb, stop)
            print(f"{shot:20} {name:27} roll {x / YD:6.1f} yd")
