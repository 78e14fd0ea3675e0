//! The shapes a scene's values are written in (an inertia, an attitude, one number or a list) and
//! the checks every table applies to them, each failure a [`FieldError`] naming the dotted field.
//!
//! The shapes read themselves with messages a scene author understands: `inertia = "x"` says
//! "expected a number, a list of principal moments or a matrix (a list of rows)", not serde's
//! "data did not match any variant of untagged enum".

use lie_groups::{LieGroup, So3};
use nalgebra::{Matrix3, Quaternion, Rotation3, UnitQuaternion, Vector3};
use serde::de::{self, Deserializer, SeqAccess, Visitor};
use serde::Deserialize;
use std::fmt;

/// A check's failure: the dotted field and the message.
pub type FieldError = (String, String);

/// An inertia (or a damping): one number, a list of diagonal entries, or a matrix row by row.
#[derive(Debug, Clone, PartialEq)]
pub enum RawInertia {
    /// One number (SE(2)'s moment; a damping c I).
    Scalar(f64),
    /// Diagonal entries (principal moments).
    Diagonal(Vec<f64>),
    /// A full symmetric matrix, row by row.
    Matrix(Vec<Vec<f64>>),
}

/// One number or a list of numbers.
#[derive(Debug, Clone, PartialEq)]
pub enum RawNumbers {
    /// One number.
    Scalar(f64),
    /// A list.
    List(Vec<f64>),
}

/// An element of a list: a number or a list of numbers (a row).
enum Entry {
    Number(f64),
    Row(Vec<f64>),
}

/// Numbers, lists of numbers, and lists of lists, with one message for anything else.
struct Shape {
    expecting: &'static str,
    rows: bool,
}

impl<'de> Visitor<'de> for Shape {
    type Value = RawInertia;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(self.expecting)
    }
    fn visit_f64<E: de::Error>(self, v: f64) -> Result<RawInertia, E> {
        Ok(RawInertia::Scalar(v))
    }
    fn visit_i64<E: de::Error>(self, v: i64) -> Result<RawInertia, E> {
        Ok(RawInertia::Scalar(v as f64))
    }
    fn visit_u64<E: de::Error>(self, v: u64) -> Result<RawInertia, E> {
        Ok(RawInertia::Scalar(v as f64))
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<RawInertia, A::Error> {
        let mut numbers = Vec::new();
        let mut rows = Vec::new();
        while let Some(e) = seq.next_element_seed(EntrySeed(self.rows))? {
            match e {
                Entry::Number(x) => numbers.push(x),
                Entry::Row(r) => rows.push(r),
            }
        }
        match (numbers.is_empty(), rows.is_empty()) {
            (_, true) => Ok(RawInertia::Diagonal(numbers)),
            (true, false) => Ok(RawInertia::Matrix(rows)),
            (false, false) => Err(de::Error::custom(format!(
                "{}: a list mixes numbers and rows",
                self.expecting
            ))),
        }
    }
}

/// Reads one element of a list: a number, or (when rows are allowed) a list of numbers.
struct EntrySeed(bool);

impl<'de> de::DeserializeSeed<'de> for EntrySeed {
    type Value = Entry;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Entry, D::Error> {
        d.deserialize_any(EntryVisitor(self.0))
    }
}

struct EntryVisitor(bool);

impl<'de> Visitor<'de> for EntryVisitor {
    type Value = Entry;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(if self.0 {
            "a number or a row of numbers"
        } else {
            "a number"
        })
    }
    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Entry, E> {
        Ok(Entry::Number(v))
    }
    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Entry, E> {
        Ok(Entry::Number(v as f64))
    }
    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Entry, E> {
        Ok(Entry::Number(v as f64))
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Entry, A::Error> {
        if !self.0 {
            return Err(de::Error::invalid_type(de::Unexpected::Seq, &self));
        }
        let mut row = Vec::new();
        while let Some(x) = seq.next_element::<f64>()? {
            row.push(x);
        }
        Ok(Entry::Row(row))
    }
}

impl<'de> Deserialize<'de> for RawInertia {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(Shape {
            expecting: "a number, a list of diagonal entries (principal moments) or a matrix (a \
                        list of rows)",
            rows: true,
        })
    }
}

impl<'de> Deserialize<'de> for RawNumbers {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        match d.deserialize_any(Shape {
            expecting: "a number or a list of numbers",
            rows: false,
        })? {
            RawInertia::Scalar(x) => Ok(RawNumbers::Scalar(x)),
            RawInertia::Diagonal(v) => Ok(RawNumbers::List(v)),
            RawInertia::Matrix(_) => unreachable!("rows are refused by the visitor"),
        }
    }
}

/// An attitude, in one of several forms.
#[derive(Debug, Clone, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum RawAttitude {
    /// A rotation matrix, row by row (n×n for SO(n)); must be orthogonal with det +1.
    Matrix(Vec<Vec<f64>>),
    /// A rotation vector ω: R = exp(ω̂), rotation by |ω| radians about ω/|ω|.
    RotationVector([f64; 3]),
    /// A unit quaternion, scalar first: [w, x, y, z].
    Quaternion([f64; 4]),
    /// A planar angle in radians (SE(2)).
    Angle(f64),
}

/// `v`, when it is finite and positive.
pub fn positive(field: &str, v: f64) -> Result<f64, FieldError> {
    if !v.is_finite() {
        Err((field.into(), format!("must be a finite number, got {v}")))
    } else if v <= 0.0 {
        Err((field.into(), format!("must be positive, got {v}")))
    } else {
        Ok(v)
    }
}

/// `v`, when it is finite and ≥ 0.
pub fn non_negative(field: &str, v: f64) -> Result<f64, FieldError> {
    if v.is_finite() && v >= 0.0 {
        Ok(v)
    } else {
        Err((
            field.into(),
            format!("must be finite and non-negative, got {v}"),
        ))
    }
}

/// Every entry finite.
pub fn finite_all(field: &str, v: &[f64]) -> Result<(), FieldError> {
    match v.iter().find(|x| !x.is_finite()) {
        Some(x) => Err((field.into(), format!("must be finite, got {x}"))),
        None => Ok(()),
    }
}

/// A momentum of `len` finite components (`kind`: the system, for the message).
pub fn momentum_of_len(kind: &str, mu: &[f64], len: usize) -> Result<(), FieldError> {
    if mu.len() != len {
        return Err((
            "initial.momentum".into(),
            format!("needs {len} components for {kind}, got {}", mu.len()),
        ));
    }
    finite_all("initial.momentum", mu)
}

/// Three finite components.
pub fn vec3(field: &str, v: &[f64]) -> Result<Vector3<f64>, FieldError> {
    if v.len() != 3 {
        return Err((field.into(), format!("needs 3 components, got {}", v.len())));
    }
    finite_all(field, v)?;
    Ok(Vector3::new(v[0], v[1], v[2]))
}

/// A position in ℝ³ (the origin when absent).
pub fn position3(field: &str, raw: &Option<Vec<f64>>) -> Result<Vector3<f64>, FieldError> {
    vec3(field, raw.as_deref().unwrap_or(&[0.0; 3]))
}

/// `system.gravity` of the systems in uniform gravity along −e₃ (heavy top, quadrotor,
/// underwater vehicle): g ≥ 0, written g or `[0, 0, -g]`.
pub fn gravity_down(kind: &str, raw: &RawNumbers) -> Result<f64, FieldError> {
    let field = "system.gravity";
    let g = match raw {
        RawNumbers::Scalar(g) => *g,
        RawNumbers::List(v) if v.len() == 3 && v[0] == 0.0 && v[1] == 0.0 => -v[2],
        RawNumbers::List(v) => {
            return Err((
                field.into(),
                format!("the {kind}'s gravity points along −e₃: give g or [0, 0, -g], got {v:?}"),
            ))
        }
    };
    if !g.is_finite() || g < 0.0 {
        return Err((
            field.into(),
            format!("must be a finite g ≥ 0 (gravity −g e₃), got g = {g}"),
        ));
    }
    Ok(g)
}

/// The n×n identity, row-major.
pub fn identity_flat(n: usize) -> Vec<f64> {
    (0..n * n)
        .map(|k| if k / n == k % n { 1.0 } else { 0.0 })
        .collect()
}

/// An n×n matrix given row by row, flattened row-major; finite entries.
pub fn square(field: &str, rows: &[Vec<f64>], n: usize) -> Result<Vec<f64>, FieldError> {
    if rows.len() != n || rows.iter().any(|r| r.len() != n) {
        return Err((
            field.into(),
            format!(
                "must be {n}×{n}, got {} rows of lengths {:?}",
                rows.len(),
                rows.iter().map(Vec::len).collect::<Vec<_>>()
            ),
        ));
    }
    let flat: Vec<f64> = rows.iter().flatten().copied().collect();
    finite_all(field, &flat)?;
    Ok(flat)
}

/// Symmetric to 10⁻¹² relative, and positive definite (Cholesky succeeds).
pub fn symmetric_positive_definite(field: &str, a: &[f64], n: usize) -> Result<(), FieldError> {
    let scale = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for i in 0..n {
        for j in 0..i {
            if (a[i * n + j] - a[j * n + i]).abs() > 1e-12 * scale {
                return Err((
                    field.into(),
                    format!(
                        "must be symmetric: entry ({},{}) = {} but ({},{}) = {}",
                        i + 1,
                        j + 1,
                        a[i * n + j],
                        j + 1,
                        i + 1,
                        a[j * n + i]
                    ),
                ));
            }
        }
    }
    let m = nalgebra::DMatrix::from_row_slice(n, n, a);
    if m.cholesky().is_none() {
        return Err((
            field.into(),
            "must be positive definite (its Cholesky factorisation fails)".into(),
        ));
    }
    Ok(())
}

/// SO(n) attitudes typed in a scene are accepted when ‖RᵀR − I‖_max ≤ 10⁻⁹, the tolerance of
/// lie-groups' checked constructors (`lie_groups::so3::ORTHOGONALITY_TOLERANCE`): tight enough that
/// the invariants of the run start on the group, loose enough for ten typed digits.
pub const ATTITUDE_TOLERANCE: f64 = lie_groups::so3::ORTHOGONALITY_TOLERANCE;

/// An n×n rotation, row-major: orthogonal to [`ATTITUDE_TOLERANCE`], det +1.
pub fn special_orthogonal(field: &str, r: &[f64], n: usize) -> Result<(), FieldError> {
    let m = nalgebra::DMatrix::from_row_slice(n, n, r);
    let err = (m.transpose() * &m - nalgebra::DMatrix::identity(n, n)).amax();
    if err > ATTITUDE_TOLERANCE {
        return Err((
            field.into(),
            format!("is not orthogonal: ‖RᵀR − I‖_max = {err:.3e} > {ATTITUDE_TOLERANCE:.0e}"),
        ));
    }
    let det = m.determinant();
    if (det - 1.0).abs() > 1e-6 {
        return Err((
            field.into(),
            format!("is not a rotation: det R = {det:.6}, expected +1"),
        ));
    }
    Ok(())
}

/// The scene key that accepts an inertia no rigid body has (see [`inertia3`]).
pub const GENERALIZED_INERTIA_KEY: &str = "generalized_inertia";

/// A 3×3 inertia at `field`: 3 positive principal moments or a symmetric positive definite
/// matrix, whose principal moments satisfy the triangle inequality of a rigid body (each at most
/// the sum of the other two: I₃ = ∫(x² + y²) dm ≤ I₁ + I₂ = ∫(x² + y² + 2z²) dm), unless
/// `generalized` (the scene's `generalized_inertia = true`: a generalized inertia, e.g. of a
/// model reduced from a larger system). Equality (a flat plate) is accepted up to rounding.
pub fn inertia3(
    field: &str,
    raw: &RawInertia,
    generalized: bool,
) -> Result<Matrix3<f64>, FieldError> {
    let m = inertia3_spd(field, raw)?;
    if !generalized {
        let mut d: Vec<f64> = m.symmetric_eigenvalues().iter().copied().collect();
        d.sort_by(f64::total_cmp);
        // relative: 1e308·I must not overflow the sum
        if d[2] / 2.0 > (d[0] / 2.0 + d[1] / 2.0) * (1.0 + 1e-12) {
            return Err((
                field.into(),
                format!(
                    "principal moments {} > {} + {} break the triangle inequality of a rigid \
                     body (each at most the sum of the other two); set {} = true in [system] \
                     (or the body's entry) for a generalized inertia",
                    d[2], d[0], d[1], GENERALIZED_INERTIA_KEY
                ),
            ));
        }
    }
    Ok(m)
}

/// [`inertia3`] without the triangle inequality.
fn inertia3_spd(field: &str, raw: &RawInertia) -> Result<Matrix3<f64>, FieldError> {
    match raw {
        RawInertia::Scalar(_) => Err((
            field.into(),
            "must be 3 principal moments or a 3×3 matrix".into(),
        )),
        RawInertia::Diagonal(d) => {
            if d.len() != 3 {
                return Err((
                    field.into(),
                    format!("needs 3 principal moments, got {}", d.len()),
                ));
            }
            for &x in d {
                positive(field, x)?;
            }
            Ok(Matrix3::new(d[0], 0.0, 0.0, 0.0, d[1], 0.0, 0.0, 0.0, d[2]))
        }
        RawInertia::Matrix(m) => {
            let flat = square(field, m, 3)?;
            symmetric_positive_definite(field, &flat, 3)?;
            Ok(Matrix3::from_row_slice(&flat))
        }
    }
}

/// Quaternions are accepted when | ‖q‖ − 1 | ≤ 10⁻⁶ (six typed digits) and then normalised.
pub const QUATERNION_TOLERANCE: f64 = 1e-6;

/// `initial.attitude` on SO(3) ([`attitude3_at`]).
pub fn attitude3(raw: &Option<RawAttitude>) -> Result<Matrix3<f64>, FieldError> {
    attitude3_at("initial.attitude", raw)
}

/// An attitude at the field `prefix` (its forms at `prefix.matrix`, `prefix.quaternion`, …); the
/// identity when absent.
pub fn attitude3_at(prefix: &str, raw: &Option<RawAttitude>) -> Result<Matrix3<f64>, FieldError> {
    match raw {
        None => Ok(Matrix3::identity()),
        Some(RawAttitude::Matrix(m)) => {
            let field = &format!("{prefix}.matrix");
            let flat = square(field, m, 3)?;
            // lie-groups' checked constructor: ‖RᵀR − I‖_max and det R = +1 within
            // `lie_groups::so3::ORTHOGONALITY_TOLERANCE`.
            let r = Matrix3::from_row_slice(&flat);
            So3::from_matrix(&r)
                .map_err(|e| (field.to_string(), format!("is not a rotation: {e}")))?;
            Ok(r)
        }
        Some(RawAttitude::RotationVector(w)) => {
            finite_all(&format!("{prefix}.rotation_vector"), w)?;
            Ok(Rotation3::new(Vector3::from(*w)).into_inner())
        }
        Some(RawAttitude::Quaternion(q)) => {
            let field = &format!("{prefix}.quaternion");
            finite_all(field, q)?;
            let quat = Quaternion::new(q[0], q[1], q[2], q[3]);
            let norm = quat.norm();
            if (norm - 1.0).abs() > QUATERNION_TOLERANCE {
                return Err((
                    field.into(),
                    format!("must have unit norm (±{QUATERNION_TOLERANCE:.0e}), got ‖q‖ = {norm}"),
                ));
            }
            Ok(UnitQuaternion::from_quaternion(quat)
                .to_rotation_matrix()
                .into_inner())
        }
        Some(RawAttitude::Angle(_)) => Err((
            format!("{prefix}.angle"),
            "a planar angle is only an attitude of planar-body-se2".into(),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotation_vector_gives_the_rotation_about_its_axis() {
        let r = attitude3(&Some(RawAttitude::RotationVector([
            0.0,
            0.0,
            core::f64::consts::FRAC_PI_2,
        ])))
        .unwrap();
        // R e₁ = e₂ for a quarter turn about e₃.
        let e2 = r * Vector3::x();
        assert!((e2 - Vector3::y()).amax() < 1e-15);
    }

    #[test]
    fn quaternion_scalar_first_matches_rotation_vector() {
        let a = 0.7f64;
        let q = [(a / 2.0).cos(), (a / 2.0).sin(), 0.0, 0.0];
        let rq = attitude3(&Some(RawAttitude::Quaternion(q))).unwrap();
        let rv = attitude3(&Some(RawAttitude::RotationVector([a, 0.0, 0.0]))).unwrap();
        assert!((rq - rv).amax() < 1e-15);
    }

    #[derive(Debug, Deserialize)]
    struct T {
        i: RawInertia,
        n: Option<RawNumbers>,
    }

    #[test]
    fn shapes_read_numbers_lists_and_rows_and_say_what_they_expect() {
        let t: T = toml::from_str("i = 2\nn = [1, 2.5]").unwrap();
        assert_eq!(t.i, RawInertia::Scalar(2.0));
        assert_eq!(t.n, Some(RawNumbers::List(vec![1.0, 2.5])));
        let t: T = toml::from_str("i = [[1, 0], [0, 2.0]]").unwrap();
        assert_eq!(
            t.i,
            RawInertia::Matrix(vec![vec![1.0, 0.0], vec![0.0, 2.0]])
        );
        let t: T = toml::from_str("i = [1.0, 2.0, 3.0]").unwrap();
        assert_eq!(t.i, RawInertia::Diagonal(vec![1.0, 2.0, 3.0]));
        let e = toml::from_str::<T>("i = \"x\"").unwrap_err().to_string();
        assert!(
            e.contains("a number, a list of diagonal entries") && !e.contains("untagged"),
            "{e}"
        );
        let e = toml::from_str::<T>("i = [1.0, [2.0]]")
            .unwrap_err()
            .to_string();
        assert!(e.contains("mixes numbers and rows"), "{e}");
        let e = toml::from_str::<T>("i = 1\nn = [[1.0]]")
            .unwrap_err()
            .to_string();
        assert!(e.contains("a number"), "{e}");
    }
}
