//! Conversions between the SO(3)/SE(3) types of this crate and nalgebra's geometry types:
//! [`So3`] ↔ `Rotation3<f64>` ↔ `UnitQuaternion<f64>`, [`Se3`] ↔ `Isometry3<f64>`.
//!
//! nalgebra's types are assumed to be valid (unit quaternions normalised, rotations orthonormal),
//! so the `From` conversions are unchecked; [`So3::from_quaternion`] is the checked entry point for
//! a raw, possibly unnormalised, quaternion.

use crate::{LieError, LieGroup, Se3, So3};
use nalgebra::{Isometry3, Quaternion, Rotation3, Translation3, UnitQuaternion};

impl From<Rotation3<f64>> for So3 {
    #[inline]
    fn from(r: Rotation3<f64>) -> Self {
        So3::from_matrix_unchecked(r.matrix())
    }
}

impl From<So3> for Rotation3<f64> {
    #[inline]
    fn from(r: So3) -> Self {
        Rotation3::from_matrix_unchecked(*r.as_matrix())
    }
}

impl From<UnitQuaternion<f64>> for So3 {
    /// The rotation matrix of the unit quaternion q (q and −q give the same element).
    #[inline]
    fn from(q: UnitQuaternion<f64>) -> Self {
        So3::from_matrix_unchecked(q.to_rotation_matrix().matrix())
    }
}

impl From<So3> for UnitQuaternion<f64> {
    /// The unit quaternion of R (nalgebra's `from_rotation_matrix`, sign chosen by nalgebra).
    #[inline]
    fn from(r: So3) -> Self {
        UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(*r.as_matrix()))
    }
}

impl From<Isometry3<f64>> for Se3 {
    /// `(R, t)` of the isometry p ↦ R p + t.
    #[inline]
    fn from(iso: Isometry3<f64>) -> Self {
        Se3::from_parts(So3::from(iso.rotation), iso.translation.vector)
    }
}

impl From<Se3> for Isometry3<f64> {
    #[inline]
    fn from(g: Se3) -> Self {
        Isometry3::from_parts(
            Translation3::from(*g.translation()),
            UnitQuaternion::from(*g.rotation()),
        )
    }
}

impl So3 {
    /// The rotation of the quaternion `q / |q|` (w, i, j, k components), checked: non-finite
    /// components give [`LieError::NonFinite`], a zero (or subnormal, |q| < 1e-300) quaternion gives
    /// [`LieError::ZeroQuaternion`]. The norm is computed after scaling by the largest component, so
    /// very large quaternions do not overflow.
    pub fn from_quaternion(q: &Quaternion<f64>) -> Result<Self, LieError> {
        if !q.coords.iter().all(|x| x.is_finite()) {
            return Err(LieError::NonFinite { what: "quaternion" });
        }
        let largest = q.coords.amax();
        if largest < 1e-300 {
            return Err(LieError::ZeroQuaternion { norm: q.norm() });
        }
        let scaled = q / largest;
        Ok(So3::from(UnitQuaternion::new_unchecked(
            scaled / scaled.norm(),
        )))
    }
}
