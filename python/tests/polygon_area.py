"""Exact areas of polygons, the oracle of the backend's coverage tests: a polygon clipped to a
convex one (Sutherland-Hodgman) and its area (the shoelace formula), in plain floats."""


def clip_convex(poly, clip):
    """The part of polygon `poly` inside the convex, counter-clockwise polygon `clip`."""
    out = list(poly)
    for i in range(len(clip)):
        (ax, ay), (bx, by) = clip[i], clip[(i + 1) % len(clip)]
        src, out = out, []
        for j in range(len(src)):
            p, q = src[j], src[(j + 1) % len(src)]
            sp = (bx - ax) * (p[1] - ay) - (by - ay) * (p[0] - ax)
            sq = (bx - ax) * (q[1] - ay) - (by - ay) * (q[0] - ax)
            if sp >= 0:
                out.append(p)
            if (sp >= 0) != (sq >= 0):
                t = sp / (sp - sq)
                out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
        if not out:
            return []
    return out


def area(poly):
    """The area a simple polygon encloses, whichever its orientation."""
    return 0.5 * abs(sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(poly, poly[1:] + poly[:1])))
