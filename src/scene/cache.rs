//! Lazy constructions of one pose, with a count of what was computed.

use crate::construct::{
    AccelerationPolygon, Bennett, CouplerPoint, InstantCentre, Kisch, Klein, Ritterhaus,
    TorqueLine, VelocityLine, VelocityPolygon, VirtualCentres,
};
use crate::mechanism::Pose;
use std::cell::{Cell, OnceCell};

/// How many times each construction was computed while building a figure.
///
/// A layer asks for what it draws and nothing else: a bare mechanism
/// computes nothing, Kisch computes E but never D.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
pub struct Evaluations {
    /// D, the instantaneous centre of the rod.
    pub instant_centre: usize,
    /// E, the velocity line.
    pub velocity_line: usize,
    /// Klein's F and G (attempted: also counted when D is at infinity).
    pub klein: usize,
    /// Kisch's H, F and G.
    pub kisch: usize,
    /// Ng's OM torque line.
    pub torque_line: usize,
    /// The six virtual centres.
    pub virtual_centres: usize,
    /// Centrode curves fitted.
    pub centrodes: usize,
    /// Coupler curves fitted.
    pub coupler_curves: usize,
    /// The velocity and acceleration polygons (counted once for the
    /// pair; written only where drawn).
    #[serde(skip_serializing_if = "is_zero")]
    pub polygons: usize,
    /// Ritterhaus's K, F and G (written only where drawn).
    #[serde(skip_serializing_if = "is_zero")]
    pub ritterhaus: usize,
    /// Bennett's L, K, F and G (attempted: also counted for an offset
    /// engine, which has none; written only where drawn).
    #[serde(skip_serializing_if = "is_zero")]
    pub bennett: usize,
}

/// Whether a count is zero (left out of the metadata).
fn is_zero(n: &usize) -> bool {
    *n == 0
}

impl Evaluations {
    /// The total of all counts.
    pub fn total(&self) -> usize {
        self.instant_centre
            + self.velocity_line
            + self.klein
            + self.kisch
            + self.torque_line
            + self.virtual_centres
            + self.centrodes
            + self.coupler_curves
            + self.polygons
            + self.ritterhaus
            + self.bennett
    }

    pub(crate) fn add(&mut self, other: &Evaluations) {
        self.instant_centre += other.instant_centre;
        self.velocity_line += other.velocity_line;
        self.klein += other.klein;
        self.kisch += other.kisch;
        self.torque_line += other.torque_line;
        self.virtual_centres += other.virtual_centres;
        self.centrodes += other.centrodes;
        self.coupler_curves += other.coupler_curves;
        self.polygons += other.polygons;
        self.ritterhaus += other.ritterhaus;
        self.bennett += other.bennett;
    }
}

/// The constructions of one pose, each computed on first request and kept.
pub(crate) struct Constructions {
    pose: Pose,
    d: OnceCell<InstantCentre>,
    e: OnceCell<VelocityLine>,
    klein: OnceCell<Option<Klein>>,
    kisch: OnceCell<Kisch>,
    torque: OnceCell<TorqueLine>,
    centres: OnceCell<VirtualCentres>,
    polygons: OnceCell<(VelocityPolygon, AccelerationPolygon)>,
    ritterhaus: OnceCell<Ritterhaus>,
    bennett: OnceCell<Option<Bennett>>,
    counts: Cell<Evaluations>,
}

impl Constructions {
    pub(crate) fn new(pose: Pose) -> Self {
        Self {
            pose,
            d: OnceCell::new(),
            e: OnceCell::new(),
            klein: OnceCell::new(),
            kisch: OnceCell::new(),
            torque: OnceCell::new(),
            centres: OnceCell::new(),
            polygons: OnceCell::new(),
            ritterhaus: OnceCell::new(),
            bennett: OnceCell::new(),
            counts: Cell::new(Evaluations::default()),
        }
    }

    fn count(&self, f: impl FnOnce(&mut Evaluations)) {
        let mut c = self.counts.get();
        f(&mut c);
        self.counts.set(c);
    }

    pub(crate) fn pose(&self) -> &Pose {
        &self.pose
    }

    pub(crate) fn d(&self) -> &InstantCentre {
        self.d.get_or_init(|| {
            self.count(|c| c.instant_centre += 1);
            InstantCentre::construct(&self.pose)
        })
    }

    pub(crate) fn e(&self) -> &VelocityLine {
        self.e.get_or_init(|| {
            self.count(|c| c.velocity_line += 1);
            VelocityLine::construct(&self.pose)
        })
    }

    pub(crate) fn klein(&self) -> Option<&Klein> {
        self.klein
            .get_or_init(|| {
                let (d, e) = (self.d(), self.e());
                self.count(|c| c.klein += 1);
                Klein::construct(&self.pose, d, e)
            })
            .as_ref()
    }

    pub(crate) fn kisch(&self) -> &Kisch {
        self.kisch.get_or_init(|| {
            let e = self.e();
            self.count(|c| c.kisch += 1);
            Kisch::construct(&self.pose, e)
        })
    }

    pub(crate) fn torque(&self) -> &TorqueLine {
        self.torque.get_or_init(|| {
            let e = self.e();
            self.count(|c| c.torque_line += 1);
            TorqueLine::construct(&self.pose, e)
        })
    }

    pub(crate) fn virtual_centres(&self) -> &VirtualCentres {
        self.centres.get_or_init(|| {
            let (d, e) = (self.d(), self.e());
            self.count(|c| c.virtual_centres += 1);
            VirtualCentres::construct(&self.pose, d, e)
        })
    }

    /// The velocity and acceleration polygons with the images of
    /// `coupler` (the scene's one coupler point, so kept once).
    pub(crate) fn polygons(
        &self,
        coupler: CouplerPoint,
    ) -> &(VelocityPolygon, AccelerationPolygon) {
        self.polygons.get_or_init(|| {
            self.count(|c| c.polygons += 1);
            let v = VelocityPolygon::construct(&self.pose, Some(coupler));
            let a = AccelerationPolygon::construct(&self.pose, &v, Some(coupler));
            (v, a)
        })
    }

    pub(crate) fn ritterhaus(&self) -> &Ritterhaus {
        self.ritterhaus.get_or_init(|| {
            let e = self.e();
            self.count(|c| c.ritterhaus += 1);
            Ritterhaus::construct(&self.pose, e)
        })
    }

    pub(crate) fn bennett(&self) -> Option<&Bennett> {
        self.bennett
            .get_or_init(|| {
                self.count(|c| c.bennett += 1);
                Bennett::construct(&self.pose)
            })
            .as_ref()
    }

    pub(crate) fn note_centrode(&self) {
        self.count(|c| c.centrodes += 1);
    }

    pub(crate) fn note_coupler(&self) {
        self.count(|c| c.coupler_curves += 1);
    }

    pub(crate) fn evaluations(&self) -> Evaluations {
        self.counts.get()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{angle::Angle, mechanism::SliderCrank};

    #[test]
    fn each_construction_is_computed_once_and_kisch_needs_no_d() {
        let m = SliderCrank::in_line(0.5, 3.0).unwrap();
        let c = Constructions::new(m.pose(Angle::deg(45.0)));
        assert_eq!(c.evaluations().total(), 0);
        c.kisch();
        c.kisch();
        c.torque();
        let n = c.evaluations();
        assert_eq!((n.kisch, n.velocity_line, n.torque_line), (1, 1, 1));
        assert_eq!(n.instant_centre, 0);
        assert!(c.klein().is_some());
        assert_eq!(c.evaluations().instant_centre, 1);
    }
}
