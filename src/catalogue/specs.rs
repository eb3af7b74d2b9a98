//! The table of the named figures: each figure's spec (its name, where it
//! comes from in the seeds, its caption, the mechanism, pose and page it is
//! drawn with, its kind and builder, and the options it takes) in one
//! entry. Adding a figure is adding an entry here (and, for a diagram, the
//! file under `builders/` that builds it); [`FigureName`] and its lists are
//! made from the table.

use super::Setting;
use super::builders::{self, Builder};
use crate::chain::Inversion;
use crate::scene::Layer;
use At::{Crank, NoPose, Tilt};
use Group::{Chain, Developers, Diagrams};
use Kind::{Diagram, Mechanism};
use Setting::{
    Angle, Bore, Cylinders, Data, Fit, Fluctuation, Font, Friction, GasForce, Gravity, Mass,
    Mirror, Rod, Speed, Style,
};
use Source::{Book, Ng, Outside};

/// What the table says of one named figure.
pub(crate) struct FigureSpec {
    /// The name (`fig-67-example`).
    pub name: &'static str,
    /// The seed and the place in it the figure reproduces.
    pub source: Source,
    /// What it shows, in a sentence or two, at the seed's own parameters
    /// (the gallery's caption).
    pub caption: &'static str,
    /// The crank r and rod l of the in-line mechanism it is drawn for.
    pub mechanism: (f64, f64),
    /// The pose it is drawn at.
    pub at: At,
    /// The page's width and height, page units.
    pub page: (f64, f64),
    /// A mechanism figure or a diagram, and how it is drawn.
    pub kind: Kind,
    /// The options it takes; any other given is refused.
    pub takes: &'static [Setting],
}

/// The seed a figure comes from, and the place in it.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Source {
    /// The textbook chapter, at the section and figure given.
    Book(&'static str),
    /// Ng's paper, at the figure given.
    Ng(&'static str),
    /// Neither seed: the whole sentence saying where it comes from.
    Outside(&'static str),
}

/// The angle a figure is drawn at, in degrees.
#[derive(Debug, Clone, Copy)]
pub(crate) enum At {
    /// A crank angle: the pose whose construction is drawn.
    Crank(f64),
    /// The tilt of Ng's inclined plane, strictly between 0° and 90°.
    Tilt(f64),
    /// No pose (a diagram over a whole turn, or of no mechanism).
    NoPose,
}

impl At {
    /// The angle in degrees; 0 for [`At::NoPose`].
    pub(crate) const fn degrees(self) -> f64 {
        match self {
            At::Crank(d) | At::Tilt(d) => d,
            At::NoPose => 0.0,
        }
    }
}

/// How a named figure is drawn.
#[derive(Clone, Copy)]
pub(crate) enum Kind {
    /// A mechanism figure, a [`crate::scene::Scene`] with these layers.
    Mechanism(&'static [Layer]),
    /// A diagram of the gallery's group, built from its options by the
    /// builder.
    Diagram(Group, Builder),
}

/// The group a named figure is listed in (the gallery's sections, the
/// command line's list of names): [`FigureName::group`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Group {
    /// The mechanism figures, drawn as scenes with layers.
    Mechanisms,
    /// The diagrams of the mechanism's motion and forces.
    Diagrams,
    /// The chain of Fig. 60 and its inversions.
    Chain,
    /// For developers: the accuracy of the drawn curves.
    Developers,
}

impl Group {
    /// Every group, in the order they are listed.
    pub const ALL: [Group; 4] = [
        Group::Mechanisms,
        Group::Diagrams,
        Group::Chain,
        Group::Developers,
    ];

    /// Its heading (`Mechanism figures`, `The chain of Fig. 60`).
    pub fn heading(self) -> &'static str {
        match self {
            Group::Mechanisms => "Mechanism figures",
            Group::Diagrams => "Diagrams",
            Group::Chain => "The chain of Fig. 60",
            Group::Developers => "For developers, the accuracy of the drawn curves",
        }
    }
}

/// The table's entries make [`FigureName`] (each entry's doc comment is
/// its variant's), [`FigureName::ALL`] in the table's order and
/// [`FigureName::spec`].
macro_rules! figures {
    ($($(#[doc = $doc:literal])+ $figure:ident => $spec:expr,)+) => {
        /// A figure of the seeds.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
        #[non_exhaustive]
        pub enum FigureName {
            $($(#[doc = $doc])+ $figure,)+
        }

        impl FigureName {
            /// Every named figure, in the table's order: the mechanism
            /// figures, then the diagrams.
            pub const ALL: [FigureName; [$(stringify!($figure)),+].len()] =
                [$(FigureName::$figure),+];

            /// Its entry in the table.
            pub(crate) const fn spec(self) -> &'static FigureSpec {
                match self {
                    $(FigureName::$figure => {
                        const SPEC: FigureSpec = $spec;
                        &SPEC
                    })+
                }
            }
        }
    };
}

use crate::sources::{CHAIN_60 as CHAIN, ENGINE_35 as ENGINE, NG_RIG};

/// What a mechanism figure takes.
const SCENE: &[Setting] = &[
    Setting::Mechanism,
    Setting::Speed,
    Setting::Angle,
    Setting::Style,
    Setting::Font,
    Setting::Layers,
    Setting::Notation,
    Setting::Mirror,
    Setting::Coupler,
];

/// The mechanism setting, short for the table.
const MECH: Setting = Setting::Mechanism;

figures! {
    /// Textbook Fig. 62: the crank angle θ and the displacement x of the
    /// cross-head from mid-stroke.
    Fig62Displacement => FigureSpec {
        name: "fig-62-displacement",
        source: Book("§35, Fig. 62"),
        caption: "The engine of §35 (r = 0.5 ft, l = 3 ft) at 40°: the crank angle θ, the displacement x of the cross-head A from mid-stroke, the stroke.",
        mechanism: ENGINE,
        at: Crank(40.0),
        page: (760.0, 250.0),
        kind: Mechanism(&[Layer::Mechanism, Layer::Angles, Layer::Dimensions]),
        takes: SCENE,
    },
    /// Textbook Fig. 63: the velocity construction, D and E, the similar
    /// triangles ADB and ECB.
    Fig63Velocity => FigureSpec {
        name: "fig-63-velocity",
        source: Book("§36–37, Fig. 63"),
        caption: "At 30°: D where CB produced meets the perpendicular to the stroke at A, E where the rod produced meets the perpendicular through C; the similar triangles ADB and ECB, CE the piston’s velocity to the scale of CB.",
        mechanism: ENGINE,
        at: Crank(30.0),
        page: (760.0, 480.0),
        kind: Mechanism(&[Layer::Mechanism, Layer::Velocity]),
        takes: SCENE,
    },
    /// Textbook Fig. 65: Klein's acceleration construction.
    Fig65Klein => FigureSpec {
        name: "fig-65-klein",
        source: Book("§36, Fig. 65 (Klein’s construction)"),
        caption: "At 30°: CF parallel to DE, FG perpendicular to AB, G on the line through C; CG the piston’s acceleration to the scale ω², in an enlarged detail.",
        mechanism: ENGINE,
        at: Crank(30.0),
        page: (760.0, 480.0),
        kind: Mechanism(&[Layer::Mechanism, Layer::Klein]),
        takes: SCENE,
    },
    /// Textbook Fig. 66: Kisch's construction (D not needed, here off the
    /// page).
    Fig66Kisch => FigureSpec {
        name: "fig-66-kisch",
        source: Book("§36, Fig. 66 (Kisch’s construction)"),
        caption: "At 60°: the semicircle on AB, the arc about B through E cutting it at H, HFG perpendicular to AB; D is not needed.",
        mechanism: ENGINE,
        at: Crank(60.0),
        page: (760.0, 420.0),
        kind: Mechanism(&[Layer::Mechanism, Layer::Kisch]),
        takes: SCENE,
    },
    /// Textbook Fig. 67: the 45° engine with its velocity and acceleration
    /// scales and values.
    Fig67Example => FigureSpec {
        name: "fig-67-example",
        source: Book("§36, Fig. 67 (the engine of §35 at 45°)"),
        caption: "The engine of §35 at 45° with the velocity and Kisch’s construction and their scales: CB represents V_c = rω, CE the piston’s velocity, CG its acceleration.",
        mechanism: ENGINE,
        at: Crank(45.0),
        page: (760.0, 520.0),
        kind: Mechanism(&[Layer::Mechanism, Layer::Velocity, Layer::Kisch, Layer::Scales]),
        takes: SCENE,
    },
    /// Ng Fig. 1: the OM torque line, slider force and side thrust.
    NgFig1Torque => FigureSpec {
        name: "ng-fig-1-torque",
        source: Ng("Fig. 1 (eqs. 6, 7 and 11)"),
        caption: "Ng’s rig (r = 25 mm, l = 72 mm) at 60°: OM, the crank torque T, the slider force F_p = T/OM, the side thrust F_s and the transmission angle β.",
        mechanism: NG_RIG,
        at: Crank(60.0),
        page: (640.0, 460.0),
        kind: Mechanism(&[Layer::Mechanism, Layer::Angles, Layer::Torque, Layer::Motion]),
        takes: SCENE,
    },
    /// Ng Fig. A1: the velocity construction in Ng's letters (I, M).
    NgFigA1Velocity => FigureSpec {
        name: "ng-fig-a1-velocity",
        source: Ng("Appendix, Fig. A1 (eq. A3)"),
        caption: "At 40°, in Ng’s letters: I, the rod’s instantaneous centre, and M, with the triangles PIC and OCM.",
        mechanism: NG_RIG,
        at: Crank(40.0),
        page: (600.0, 480.0),
        kind: Mechanism(&[Layer::Mechanism, Layer::Velocity, Layer::Motion]),
        takes: SCENE,
    },
    /// Ritterhaus's construction of the piston's acceleration, with its
    /// velocity part and scales.
    RitterhausConstruction => FigureSpec {
        name: "ritterhaus-construction",
        source: Book("§36, Figs. 65–67: the piston’s acceleration ω² · CG of Klein’s and Kisch’s constructions found by Ritterhaus’s, taught beside them (docs/polygons.md); not drawn in the chapter"),
        caption: "Ritterhaus’s construction at 30°: E where the rod produced meets the perpendicular through C (CE the piston’s velocity), EK parallel to AC to the crank produced, KF perpendicular to the stroke, FG perpendicular to AB; CG the piston’s acceleration to the scale ω².",
        mechanism: ENGINE,
        at: Crank(30.0),
        page: (760.0, 560.0),
        kind: Mechanism(&[Layer::Mechanism, Layer::Ritterhaus, Layer::Scales]),
        takes: SCENE,
    },
    /// Bennett's construction of the piston's acceleration (the in-line
    /// engine's), with its velocity part and scales.
    BennettConstruction => FigureSpec {
        name: "bennett-construction",
        source: Book("§36, Figs. 65–67: the piston’s acceleration ω² · CG of Klein’s and Kisch’s constructions found by Bennett’s, taught beside them (docs/polygons.md); not drawn in the chapter"),
        caption: "Bennett’s construction at 30°: L at r²/l from B on the rod, LK perpendicular to AB to the line of stroke, KF perpendicular to the stroke, FG perpendicular to AB; CG the piston’s acceleration to the scale ω², CE its velocity.",
        mechanism: ENGINE,
        at: Crank(30.0),
        page: (760.0, 560.0),
        kind: Mechanism(&[Layer::Mechanism, Layer::Bennett, Layer::Scales]),
        takes: SCENE,
    },
    /// The relative-velocity method: the velocity and acceleration
    /// polygons of the §35 engine, with the images of the rod's mid-point.
    VelocityAccelerationPolygons => FigureSpec {
        name: "velocity-acceleration-polygons",
        source: Book("§36–37: the piston’s velocity CE and Klein’s acceleration CG (Figs. 63, 65 and 67) found again by the relative-velocity method, the velocity and acceleration polygons of the course in the kinematics of machines (docs/polygons.md); not drawn in the chapter"),
        caption: "The relative-velocity method at 45°: the velocity polygon cba (ab perpendicular to AB) and the acceleration polygon c′b′xa′ (ω²r, the rod’s normal component ab²/AB and its tangential component), with q and q′ the images of the rod’s mid-point Q, to the scales stated.",
        mechanism: ENGINE,
        at: Crank(45.0),
        page: (760.0, 720.0),
        kind: Mechanism(&[Layer::Mechanism, Layer::Polygons]),
        takes: SCENE,
    },
    /// Textbook Fig. 61: the rod's fixed centrode (full) and moving
    /// centrode (dotted), with the construction of D for one pose.
    Fig61Centrodes => FigureSpec {
        name: "fig-61-centrodes",
        source: Book("§34, Fig. 61"),
        caption: "The rod’s fixed centrode (full) and moving centrode (dotted, carried with the rod at 35°), touching at D; drawn with n = 2.5, on which the two are far enough apart to read.",
        mechanism: (0.5, 1.25),
        at: Crank(35.0),
        page: (760.0, 600.0),
        kind: Diagram(Diagrams, builders::centrodes::build),
        takes: &[MECH, Angle, Style, Font, Mirror],
    },
    /// Textbook Fig. 64: the polar diagram of piston velocity (E′ on the
    /// crank, CE′ = CE), the velocity on a distance base (E″ over A) and on
    /// a time base against simple harmonic motion.
    Fig64VelocityDiagrams => FigureSpec {
        name: "fig-64-velocity-diagrams",
        source: Book("§36, Fig. 64"),
        caption: "At 50°: the polar diagram of piston velocity (CE′ = CE on the crank), the velocity on a distance base and on a time base against simple harmonic motion.",
        mechanism: ENGINE,
        at: Crank(50.0),
        page: (860.0, 860.0),
        kind: Diagram(Diagrams, builders::velocity::build),
        takes: &[MECH, Speed, Angle, Style, Font, Mirror],
    },
    /// Piston acceleration on a distance base and a time base against
    /// simple harmonic motion, and a polar acceleration diagram.
    AccelerationDiagrams => FigureSpec {
        name: "acceleration-diagrams",
        source: Book("§35–36, eq. (3) and the acceleration scale of Fig. 67; the chapter describes these diagrams without a figure"),
        caption: "The piston’s acceleration on a distance base and a time base against simple harmonic motion, and the polar diagram CG′ = CG on the crank.",
        mechanism: ENGINE,
        at: Crank(45.0),
        page: (900.0, 760.0),
        kind: Diagram(Diagrams, builders::acceleration::build),
        takes: &[MECH, Speed, Angle, Style, Font],
    },
    /// The rod's angular velocity and acceleration against θ (§37), with
    /// eq. (2a).
    RodMotion => FigureSpec {
        name: "rod-motion",
        source: Book("§37, the rod’s angular motion and eq. (2a); no figure in the chapter"),
        caption: "The rod’s angular velocity and acceleration against θ at 250 rpm, eq. (2a) dashed, the values at 45° marked.",
        mechanism: ENGINE,
        at: Crank(45.0),
        page: (760.0, 640.0),
        kind: Diagram(Diagrams, builders::rod::build),
        takes: &[MECH, Speed, Angle, Style, Font],
    },
    /// The error of the textbook's approximations (eq. 2, 3, 2a and the
    /// obliquity term) against θ for n = 4, 5, 6.
    ApproximationError => FigureSpec {
        name: "approximation-error",
        source: Book("§35 and §37, eqs. (2), (3), (2a) and the error due to obliquity; no figure in the chapter"),
        caption: "The textbook’s approximations less the exact values for n = 4, 5 and 6, scaled: the error due to obliquity, eqs. (2), (3) and (2a).",
        mechanism: ENGINE,
        at: NoPose,
        page: (900.0, 680.0),
        kind: Diagram(Diagrams, builders::approximation::build),
        takes: &[Style, Font],
    },
    /// Ovals traced by points of the rod (§34).
    CouplerCurves => FigureSpec {
        name: "coupler-curves",
        source: Book("§34, the ovals traced by points of the rod; no figure in the chapter"),
        caption: "The ovals traced by the rod’s points at ¼, ½ and ¾ of AB from A, on the mechanism at 40°.",
        mechanism: ENGINE,
        at: Crank(40.0),
        page: (760.0, 340.0),
        kind: Diagram(Diagrams, builders::coupler::build),
        takes: &[MECH, Angle, Style, Font, Mirror],
    },
    /// Ng Fig. 2: the block on an inclined plane, μ = tan φ.
    NgFig2Incline => FigureSpec {
        name: "ng-fig-2-incline",
        source: Ng("Fig. 2 (eq. 10)"),
        caption: "The block on a plane tilted at 45°: its weight, the normal force N and the friction μN, so μ = tan 45° = 1.",
        mechanism: NG_RIG,
        at: Tilt(45.0),
        page: (620.0, 520.0),
        kind: Diagram(Diagrams, builders::incline::build),
        takes: &[Angle, Style, Font],
    },
    /// Ng Fig. 7: the calibration points, fitted line(s), equation and R².
    NgFig7Calibration => FigureSpec {
        name: "ng-fig-7-calibration",
        source: Ng("Fig. 7 (Table 1)"),
        caption: "Table 1’s calibration points, the fits through the origin and with an intercept, R² about zero (Ng’s 0.9998) and about the mean.",
        mechanism: NG_RIG,
        at: NoPose,
        page: (640.0, 460.0),
        kind: Diagram(Diagrams, builders::calibration::build),
        takes: &[Data, Fit, Style, Font],
    },
    /// Ng Fig. 8: F and F′ (theory) against θ with the measured F′, and the
    /// transmission angle.
    NgFig8Forces => FigureSpec {
        name: "ng-fig-8-forces",
        source: Ng("Fig. 8 (Table 2, eqs. 6, 8 and 11)"),
        caption: "F and F′ against θ for T = 264.87 N·mm and μ = 1, the measured F′, the least F and the transmission angle.",
        mechanism: NG_RIG,
        at: NoPose,
        page: (760.0, 700.0),
        kind: Diagram(Diagrams, builders::forces::build),
        takes: &[MECH, Data, Style, Font],
    },
    /// The curve engine's benchmark: segments and time against measured
    /// error, log–log (docs/curve-benchmarks.csv).
    CurveBenchmark => FigureSpec {
        name: "curve-benchmark",
        source: Outside("Not from the sources: the benchmark of the curve engine that traces every diagram (docs/benchmarks.md)"),
        caption: "Segments and time against the measured error of the cubic, adaptive-polyline and uniform methods, log–log.",
        mechanism: ENGINE,
        at: NoPose,
        page: (900.0, 540.0),
        kind: Diagram(Developers, builders::benchmark::build),
        takes: &[Data, Style, Font],
    },
    /// Textbook Fig. 60: (a) the quadric crank chain, (b) the block in a
    /// curved slot with its centre O_cd, (c) the straight slot, O_cd at
    /// infinity; links a, b, c, d, one crank angle.
    Fig60Chains => FigureSpec {
        name: "fig-60-chains",
        source: Book("§34, Fig. 60"),
        caption: "(a) The quadric crank chain, (b) the block in a curved slot about O_cd, (c) the straight slot with O_cd at infinity; links a, b, c, d at 50°.",
        mechanism: CHAIN,
        at: Crank(50.0),
        page: (900.0, 420.0),
        kind: Diagram(Chain, builders::chains::build),
        takes: &[MECH, Angle, Style, Font],
    },
    /// Inversion 1, the frame d fixed: the direct-acting engine, with its
    /// six virtual centres.
    Inversion1Engine => FigureSpec {
        name: "inversion-1-engine",
        source: Book("§34, the first inversion of the chain of Fig. 60"),
        caption: "The frame d fixed (the direct-acting engine) at 60°: the six virtual centres, O_bd and O_ac by Kennedy’s lines, O_cd at infinity.",
        mechanism: CHAIN,
        at: Crank(60.0),
        page: (760.0, 620.0),
        kind: Diagram(Chain, |ctx| builders::inversions::build(ctx, Inversion::Frame)),
        takes: &[MECH, Angle, Style, Font],
    },
    /// Inversion 2, the crank a fixed: the rotating block (Whitworth's
    /// quick return, the Gnome engine).
    Inversion2RotatingBlock => FigureSpec {
        name: "inversion-2-rotating-block",
        source: Book("§34, the second inversion of the chain of Fig. 60"),
        caption: "The crank a fixed (Whitworth’s quick return, the Gnome engine): the slotted frame turning about C, the rod about B.",
        mechanism: CHAIN,
        at: Crank(60.0),
        page: (760.0, 620.0),
        kind: Diagram(Chain, |ctx| builders::inversions::build(ctx, Inversion::Crank)),
        takes: &[MECH, Angle, Style, Font],
    },
    /// Inversion 3, the rod b fixed: the oscillating cylinder, the crank
    /// and slotted lever quick return.
    Inversion3OscillatingCylinder => FigureSpec {
        name: "inversion-3-oscillating-cylinder",
        source: Book("§34, the third inversion of the chain of Fig. 60"),
        caption: "The rod b fixed (the oscillating cylinder, the crank and slotted lever): the block swinging about A, the quick return’s time ratio.",
        mechanism: CHAIN,
        at: Crank(60.0),
        page: (760.0, 620.0),
        kind: Diagram(Chain, |ctx| builders::inversions::build(ctx, Inversion::Rod)),
        takes: &[MECH, Angle, Style, Font],
    },
    /// Inversion 4, the block c fixed: the hand pump.
    Inversion4HandPump => FigureSpec {
        name: "inversion-4-hand-pump",
        source: Book("§34, the fourth inversion of the chain of Fig. 60"),
        caption: "The block c fixed (the hand pump): the plunger sliding in the fixed barrel, the handle swinging about A.",
        mechanism: CHAIN,
        at: Crank(60.0),
        page: (760.0, 620.0),
        kind: Diagram(Chain, |ctx| builders::inversions::build(ctx, Inversion::Slider)),
        takes: &[MECH, Angle, Style, Font],
    },
    /// Inversion 2 by the relative-velocity method: the rotating block
    /// (Whitworth's quick return) beside its velocity polygon and its
    /// acceleration polygon closed by the Coriolis component.
    CoriolisInversion2 => FigureSpec {
        name: "coriolis-inversion-2",
        source: Book("§34, the second inversion of the chain of Fig. 60 (Whitworth’s quick return), its velocity and acceleration found by the relative-velocity method with the Coriolis component of a course in the kinematics of machines (docs/polygons.md); not drawn in the chapter"),
        caption: "Whitworth’s quick return (the crank a fixed) at 60°: the velocity polygon o a a_d and the acceleration polygon o′ a′ n a′_d k, closed by the Coriolis component 2ω_d v, the block’s sliding velocity turned 90° in the sense of ω_d, to the scales of their bars.",
        mechanism: CHAIN,
        at: Crank(60.0),
        page: (760.0, 760.0),
        kind: Diagram(Chain, |ctx| builders::coriolis::build(ctx, Inversion::Crank)),
        takes: &[MECH, Speed, Angle, Style, Font],
    },
    /// Inversion 3 by the relative-velocity method: the crank and slotted
    /// lever (the oscillating cylinder) beside its velocity polygon and
    /// its acceleration polygon closed by the Coriolis component.
    CoriolisInversion3 => FigureSpec {
        name: "coriolis-inversion-3",
        source: Book("§34, the third inversion of the chain of Fig. 60 (the crank and slotted lever, the oscillating cylinder), its velocity and acceleration found by the relative-velocity method with the Coriolis component of a course in the kinematics of machines (docs/polygons.md); not drawn in the chapter"),
        caption: "The crank and slotted lever (the rod b fixed) at 60°: the velocity polygon o c a_d and the acceleration polygon o′ c′ n a′_d k, closed by the Coriolis component 2ω_d v, the lever’s sliding velocity turned 90° in the sense of ω_d, to the scales of their bars.",
        mechanism: CHAIN,
        at: Crank(60.0),
        page: (760.0, 760.0),
        kind: Diagram(Chain, |ctx| builders::coriolis::build(ctx, Inversion::Rod)),
        takes: &[MECH, Speed, Angle, Style, Font],
    },
    /// The crank and slotted lever's tool: its velocity and acceleration
    /// against the driver's turn over the cutting and return strokes, the
    /// time ratio.
    QuickReturnSlottedLever => FigureSpec {
        name: "quick-return-slotted-lever",
        source: Book("§34, the third inversion of the chain of Fig. 60 (the crank and slotted lever quick return): the tool’s motion over its strokes, as a course in the kinematics of machines works it (docs/quick-return.md); not drawn in the chapter"),
        caption: "The crank and slotted lever (r = 0.5, l = 1.5, the arm L = l + r) at 250 rpm: the tool’s velocity and acceleration against the driver’s turn, which is time, over the cutting stroke (full, 218.9°) and the quicker return (dashed, 141.1°), the strokes ending at θ = 90° and 270°; time ratio 1.552.",
        mechanism: CHAIN,
        at: Crank(60.0),
        page: (760.0, 700.0),
        kind: Diagram(Chain, |ctx| builders::quick_return::build(ctx, Inversion::Rod)),
        takes: &[MECH, Speed, Angle, Style, Font],
    },
    /// Whitworth's quick return's tool: its velocity and acceleration
    /// against the driver's turn over the cutting and return strokes, the
    /// time ratio.
    QuickReturnWhitworth => FigureSpec {
        name: "quick-return-whitworth",
        source: Book("§34, the second inversion of the chain of Fig. 60 (Whitworth’s quick return): the tool’s motion over its strokes, as a course in the kinematics of machines works it (docs/quick-return.md); not drawn in the chapter"),
        caption: "Whitworth’s quick return (r = 0.5, l = 1.5, the arm L = l + r) at 250 rpm of the rod: the tool’s velocity and acceleration against the driver’s turn, which is time, over the cutting stroke (full, 218.9°) and the quicker return (dashed, 141.1°), the strokes ending at θ = 90° and 270°; time ratio 1.552.",
        mechanism: CHAIN,
        at: Crank(60.0),
        page: (760.0, 700.0),
        kind: Diagram(Chain, |ctx| builders::quick_return::build(ctx, Inversion::Crank)),
        takes: &[MECH, Speed, Angle, Style, Font],
    },
    /// The curved slot's difference from the straight slot against its
    /// radius ρ from 1 to 1e15, log–log.
    SlotConvergence => FigureSpec {
        name: "slot-convergence",
        source: Book("§34, Fig. 60 (b) against (c): the curved slot tending to the straight one; no figure in the chapter"),
        caption: "The block in a slot of radius ρ against the straight slot: the largest differences of position, velocity and acceleration for ρ = 1 to 10¹⁵, log–log.",
        mechanism: (0.2, 0.6),
        at: NoPose,
        page: (760.0, 560.0),
        kind: Diagram(Chain, builders::convergence::build),
        takes: &[MECH, Style, Font],
    },
    /// The turning-moment diagram of an engine (§37's inertia force and
    /// Ng's T = F · OM over a turn) with its mean line and the areas
    /// between them, and the flywheel's energy diagram.
    TurningMoment => FigureSpec {
        name: "turning-moment",
        source: Book("§35–37 (the piston’s acceleration, Klein’s CG) with Ng’s T = F · OM, carried over a turn by standard engine dynamics (docs/dynamics.md); no figure in either seed"),
        caption: "The §35 engine at 250 rpm with a 10 slug reciprocating mass and a steam indicator diagram: the torque on the crank against θ, its mean line and the areas between them, and the energy stored in the flywheel with its fluctuation ΔE.",
        mechanism: ENGINE,
        at: NoPose,
        page: (900.0, 760.0),
        kind: Diagram(Diagrams, builders::turning::build),
        takes: &[MECH, Speed, Data, Bore, GasForce, Mass, Gravity, Friction, Style, Font],
    },
    /// The inertia force of the reciprocating parts on the mechanism:
    /// Klein's CG read as the piston's acceleration and scaled by m ω² to
    /// the force, drawn at the cross-head against the acceleration,
    /// resolved along the rod and on the guides, and the crank effort
    /// T = F · OM through Ng's torque line.
    InertiaForce => FigureSpec {
        name: "inertia-force",
        source: Book("§36, Fig. 65 (Klein’s CG, the piston’s acceleration to the scale ω²) with Ng’s T = F · OM (eq. 2), the inertia force by d’Alembert (docs/dynamics.md §2); no figure in either seed"),
        caption: "The §35 engine at 30° and 250 rpm with a 10 slug reciprocating mass: Klein’s construction, CG read as the inertia force m ω² CG and drawn at the cross-head against the acceleration; the force resolved along the rod and on the guides; the crank effort T = F · OM through Ng’s OM (= CE).",
        mechanism: ENGINE,
        at: Crank(30.0),
        page: (760.0, 760.0),
        kind: Diagram(Diagrams, builders::inertia::build),
        takes: &[MECH, Speed, Angle, Mass, Style, Font, Mirror],
    },
    /// The primary and secondary unbalanced forces of the reciprocating
    /// parts (m r ω² cos θ, m r ω² cos 2θ / n), their sum and the exact
    /// inertia force against θ, and what the two terms leave out.
    PrimarySecondary => FigureSpec {
        name: "primary-secondary",
        source: Book("§35, eq. (3) and its table of cos θ + cos 2θ / n, carried on by the balancing of the reciprocating parts (docs/dynamics.md §6); no figure in either seed"),
        caption: "The §35 engine at 250 rpm with a 10 slug reciprocating mass: the primary force m r ω² cos θ, the secondary m r ω² cos 2θ / n, their sum and the exact inertia force against θ, and the exact force less the two terms.",
        mechanism: ENGINE,
        at: NoPose,
        page: (900.0, 760.0),
        kind: Diagram(Diagrams, builders::unbalanced::build),
        takes: &[MECH, Speed, Mass, Style, Font],
    },
    /// The direct and reverse crank method: the primary force as the
    /// resultant of cranks at ±θ, the secondary as that of cranks of
    /// radius r/4n at ±2θ, their components on the line of stroke summing
    /// to the force.
    DirectReverseCranks => FigureSpec {
        name: "direct-reverse-cranks",
        source: Book("§35, eq. (3): its two terms as the direct and reverse cranks of the balancing of the reciprocating parts (docs/dynamics.md §6); no figure in either seed"),
        caption: "The §35 engine at 30° and 250 rpm with a 10 slug reciprocating mass: the primary force as the resultant of the direct and reverse cranks at ±θ, each carrying m/2 at r, the secondary as that of cranks at ±2θ, each m/2 at r/4n turning at 2ω, and the two on the line of stroke against the exact inertia force.",
        mechanism: ENGINE,
        at: Crank(30.0),
        page: (900.0, 660.0),
        kind: Diagram(Diagrams, builders::cranks::build),
        takes: &[MECH, Speed, Angle, Mass, Style, Font],
    },
    /// The force and couple polygons of an in-line engine's balance: the
    /// primary and secondary forces and couples of three cylinders at
    /// 120°, each polygon's closing side its resultant.
    InlineBalance => FigureSpec {
        name: "inline-balance",
        source: Book("§35, eq. (3): its two terms summed over the cylinders of an in-line engine, the balancing of the reciprocating masses as a course in the dynamics of machines draws it (docs/dynamics.md §6); no figure in either seed"),
        caption: "Three cylinders in line with cranks at 120°, a pitch of 1 and the reference plane through the middle one, n = 6: the primary and secondary force polygons close (the forces balance), the couple polygons do not, their closing sides √3 and √3/n the unbalanced couples (by default; other cranks and planes may be given).",
        mechanism: ENGINE,
        at: NoPose,
        page: (900.0, 760.0),
        kind: Diagram(Diagrams, builders::balance::build),
        takes: &[MECH, Style, Font, Cylinders],
    },
    /// The polar load diagram of the crank pin over a turn, with and
    /// without the rod's inertia, in fixed axes and relative to the crank.
    CrankPinLoads => FigureSpec {
        name: "crank-pin-loads",
        source: Book("§35–37 (the piston’s acceleration) with Ng’s forces through the rod, carried to the bearing loads of the whole engine by Newton–Euler on the slider and the rod (docs/dynamics.md §3); no figure in either seed"),
        caption: "The turning-moment figure’s engine with an illustrative rod (mass 0.6 of the reciprocating mass, its centre of mass l/3 from the crank pin, radius of gyration 0.3 l): the load of the rod on the crank pin over a turn, with the rod’s inertia and without it, (a) in fixed axes (the main bearing’s load) and (b) relative to the crank.",
        mechanism: ENGINE,
        at: NoPose,
        page: (900.0, 760.0),
        kind: Diagram(Diagrams, builders::loads::build),
        takes: &[MECH, Speed, Data, Bore, GasForce, Mass, Rod, Gravity, Friction, Style, Font],
    },
    /// The flywheel: the energy stored above its least over the turn,
    /// rising by the fluctuation of energy ΔE, and the crank speed with
    /// the flywheel I = ΔE / (ω² C_s) of a coefficient of fluctuation of
    /// speed C_s.
    Flywheel => FigureSpec {
        name: "flywheel",
        source: Book("§35–37 (the piston’s acceleration) with Ng’s T = F · OM, carried over a turn to the fluctuation of energy and the flywheel (docs/dynamics.md §4–5); no figure in either seed"),
        caption: "The turning-moment figure’s engine: the energy stored above its least over the turn, rising by ΔE, and the crank speed with the flywheel I = ΔE/(ω² C_s) for C_s = 0.02, between ω_min and ω_max.",
        mechanism: ENGINE,
        at: NoPose,
        page: (900.0, 760.0),
        kind: Diagram(Diagrams, builders::flywheel::build),
        takes: &[
            MECH,
            Speed,
            Data,
            Bore,
            GasForce,
            Mass,
            Fluctuation,
            Gravity,
            Friction,
            Style,
            Font,
        ],
    },
}

impl FigureName {
    /// The mechanism figures, drawn by a [`crate::scene::Scene`], in the
    /// table's order.
    pub const SCENES: [FigureName; FigureName::count(false)] = FigureName::pick(false);

    /// The diagrams: plots, polar diagrams, centrodes, coupler curves and
    /// the chain's figures, in the table's order.
    pub const DIAGRAMS: [FigureName; FigureName::count(true)] = FigureName::pick(true);

    /// How many of the table's figures are diagrams (`diagrams`) or
    /// mechanism figures.
    // cannot fail: evaluated when the crate is built, where an index out of
    // range is a build error.
    #[allow(clippy::indexing_slicing)]
    const fn count(diagrams: bool) -> usize {
        let mut n = 0;
        let mut i = 0;
        while i < FigureName::ALL.len() {
            if FigureName::ALL[i].is_diagram() == diagrams {
                n += 1;
            }
            i += 1;
        }
        n
    }

    /// The `N` diagrams (`diagrams`) or mechanism figures of the table, in
    /// its order.
    // cannot fail: evaluated when the crate is built, where an index out of
    // range is a build error.
    #[allow(clippy::indexing_slicing)]
    const fn pick<const N: usize>(diagrams: bool) -> [FigureName; N] {
        let mut out = [FigureName::ALL[0]; N];
        let mut n = 0;
        let mut i = 0;
        while i < FigureName::ALL.len() {
            if FigureName::ALL[i].is_diagram() == diagrams {
                out[n] = FigureName::ALL[i];
                n += 1;
            }
            i += 1;
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_lists_the_mechanism_figures_then_the_diagrams() {
        let order: Vec<FigureName> = FigureName::SCENES
            .into_iter()
            .chain(FigureName::DIAGRAMS)
            .collect();
        assert_eq!(order, FigureName::ALL);
        assert_eq!(FigureName::SCENES.len(), 10);
        assert_eq!(FigureName::DIAGRAMS.len(), 27);
    }

    #[test]
    fn a_diagram_is_in_a_diagrams_group_and_a_scene_in_the_mechanisms() {
        for f in FigureName::ALL {
            assert_eq!(
                f.group() == Group::Mechanisms,
                !f.is_diagram(),
                "{}",
                f.name()
            );
        }
    }

    #[test]
    fn each_entry_names_one_figure_and_takes_each_option_once() {
        let mut names: Vec<&str> = FigureName::ALL.iter().map(|f| f.spec().name).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), FigureName::ALL.len());
        for f in FigureName::ALL {
            let spec = f.spec();
            for (i, s) in spec.takes.iter().enumerate() {
                assert!(!spec.takes[i + 1..].contains(s), "{}: {s:?}", spec.name);
            }
            // Every figure may be drawn in either style and face.
            assert!(spec.takes.contains(&Style) && spec.takes.contains(&Font));
            // The layers, the letters and a pose's angle where there is one.
            let scene = matches!(spec.kind, Mechanism(_));
            assert_eq!(
                spec.takes.contains(&Setting::Layers),
                scene,
                "{}",
                spec.name
            );
            assert_eq!(spec.takes.contains(&Setting::Notation), scene);
            if spec.takes.contains(&Angle) {
                assert!(!matches!(spec.at, NoPose), "{}", spec.name);
            }
        }
    }
}
