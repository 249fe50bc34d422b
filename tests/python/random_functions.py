"""Random functions for the Python tests, shared by the files that compare evaluations."""
import genmod as gm


def random_function(rng, depth):
    """A random function of x(0), x(1), x(2) from the elementary operators."""
    if depth == 0:
        return gm.x(int(rng.integers(3))) if rng.random() < 0.7 else gm.Fn(float(rng.uniform(-2, 2)))
    a, b = random_function(rng, depth - 1), random_function(rng, depth - 1)
    op = int(rng.integers(10))
    return [lambda: a + b, lambda: a - b, lambda: a * b, lambda: a / (b * b + 0.5), lambda: gm.sin(a),
            lambda: gm.exp(gm.min(a, 1.0)), lambda: gm.max(a, b), lambda: gm.sqrt(gm.abs(a)),
            lambda: gm.select(a < b, a, b), lambda: a ** 2][op]()
