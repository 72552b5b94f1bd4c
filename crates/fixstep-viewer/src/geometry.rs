//! Small `f64` vector helpers for drawing. The viewer is an edge: it reads the fixed-point
//! state once, converts it to floats here, and never feeds anything back.

/// A point or direction in world space, m.
pub type P3 = [f64; 3];

/// a + b.
pub fn add(a: P3, b: P3) -> P3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// a − b.
pub fn sub(a: P3, b: P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// s a.
pub fn scale(a: P3, s: f64) -> P3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// a · b.
pub fn dot(a: P3, b: P3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// a × b.
pub fn cross(a: P3, b: P3) -> P3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// a / |a|, or zero for a zero vector.
pub fn normalize(a: P3) -> P3 {
    let length = dot(a, a).sqrt();
    if length > 0.0 {
        scale(a, 1.0 / length)
    } else {
        [0.0; 3]
    }
}

/// A rigid placement in floats: x ↦ R x + t.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    /// Columns of the rotation matrix R: the body's x, y and z axes in world space.
    pub axes: [P3; 3],
    /// The translation t, m.
    pub origin: P3,
}

impl Pose {
    /// The pose of a unit quaternion (w, x, y, z) and a position, by the usual
    /// quaternion-to-matrix formula R = I + 2w\[v\]ₓ + 2\[v\]ₓ².
    pub fn from_quaternion(q: [f64; 4], origin: P3) -> Self {
        let [w, x, y, z] = q;
        let axes = [
            [
                1.0 - 2.0 * (y * y + z * z),
                2.0 * (x * y + w * z),
                2.0 * (x * z - w * y),
            ],
            [
                2.0 * (x * y - w * z),
                1.0 - 2.0 * (x * x + z * z),
                2.0 * (y * z + w * x),
            ],
            [
                2.0 * (x * z + w * y),
                2.0 * (y * z - w * x),
                1.0 - 2.0 * (x * x + y * y),
            ],
        ];
        Self { axes, origin }
    }

    /// A local point in world space: R p + t.
    pub fn point(&self, p: P3) -> P3 {
        add(self.vector(p), self.origin)
    }

    /// A local direction in world space: R v.
    pub fn vector(&self, v: P3) -> P3 {
        add(
            add(scale(self.axes[0], v[0]), scale(self.axes[1], v[1])),
            scale(self.axes[2], v[2]),
        )
    }

    /// The placement of `inner` (given in this pose's frame) in world space.
    pub fn compose(&self, inner: &Pose) -> Pose {
        Pose {
            axes: inner.axes.map(|axis| self.vector(axis)),
            origin: self.point(inner.origin),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quarter_turn_about_z_maps_x_to_y() {
        let half = std::f64::consts::FRAC_PI_4;
        let pose = Pose::from_quaternion([half.cos(), 0.0, 0.0, half.sin()], [1.0, 0.0, 0.0]);
        let p = pose.point([1.0, 0.0, 0.0]);
        assert!((p[0] - 1.0).abs() < 1e-12 && (p[1] - 1.0).abs() < 1e-12);
    }
}
