//! Where each named figure comes from in the seeds, and what it shows: the
//! captions of the gallery.

use super::FigureName;

/// The textbook chapter, as the captions name it.
const BOOK: &str = "Textbook, Chapter IV “Slider-crank chains”";

/// Ng's paper, as the captions name it.
const NG: &str = "Ng, “A slider-crank experiment to determine the action of static forces”";

impl FigureName {
    /// The seed, section and figure it reproduces (`Textbook, Chapter IV
    /// “Slider-crank chains”, §36, Fig. 67`); for a figure the seed
    /// describes without drawing, the section and equations it is drawn
    /// from; `curve-benchmark` says it is not from the seeds.
    pub fn source(&self) -> String {
        let (seed, place) = match self {
            FigureName::Fig62Displacement => (BOOK, "§35, Fig. 62"),
            FigureName::Fig63Velocity => (BOOK, "§36–37, Fig. 63"),
            FigureName::Fig65Klein => (BOOK, "§36, Fig. 65 (Klein’s construction)"),
            FigureName::Fig66Kisch => (BOOK, "§36, Fig. 66 (Kisch’s construction)"),
            FigureName::Fig67Example => (BOOK, "§36, Fig. 67 (the engine of §35 at 45°)"),
            FigureName::NgFig1Torque => (NG, "Fig. 1 (eqs. 6, 7 and 11)"),
            FigureName::NgFigA1Velocity => (NG, "Appendix, Fig. A1 (eq. A3)"),
            FigureName::Fig61Centrodes => (BOOK, "§34, Fig. 61"),
            FigureName::Fig64VelocityDiagrams => (BOOK, "§36, Fig. 64"),
            FigureName::AccelerationDiagrams => (
                BOOK,
                "§35–36, eq. (3) and the acceleration scale of Fig. 67; the chapter describes these diagrams without a figure",
            ),
            FigureName::RodMotion => (
                BOOK,
                "§37, the rod’s angular motion and eq. (2a); no figure in the chapter",
            ),
            FigureName::ApproximationError => (
                BOOK,
                "§35 and §37, eqs. (2), (3), (2a) and the error due to obliquity; no figure in the chapter",
            ),
            FigureName::CouplerCurves => (
                BOOK,
                "§34, the ovals traced by points of the rod; no figure in the chapter",
            ),
            FigureName::NgFig2Incline => (NG, "Fig. 2 (eq. 10)"),
            FigureName::NgFig7Calibration => (NG, "Fig. 7 (Table 1)"),
            FigureName::NgFig8Forces => (NG, "Fig. 8 (Table 2, eqs. 6, 8 and 11)"),
            FigureName::CurveBenchmark => {
                return "Not from the sources: the benchmark of the curve engine that traces every diagram (docs/benchmarks.md)".into();
            }
            FigureName::Fig60Chains => (BOOK, "§34, Fig. 60"),
            FigureName::TurningMoment => (
                BOOK,
                "§35–37 (the piston’s acceleration, Klein’s CG) with Ng’s T = F · OM, carried over a turn by standard engine dynamics (docs/dynamics.md); no figure in either seed",
            ),
            FigureName::InertiaForce => (
                BOOK,
                "§36, Fig. 65 (Klein’s CG, the piston’s acceleration to the scale ω²) with Ng’s T = F · OM (eq. 2), the inertia force by d’Alembert (docs/dynamics.md §2); no figure in either seed",
            ),
            FigureName::PrimarySecondary => (
                BOOK,
                "§35, eq. (3) and its table of cos θ + cos 2θ / n, carried on by the balancing of the reciprocating parts (docs/dynamics.md §6); no figure in either seed",
            ),
            FigureName::DirectReverseCranks => (
                BOOK,
                "§35, eq. (3): its two terms as the direct and reverse cranks of the balancing of the reciprocating parts (docs/dynamics.md §6); no figure in either seed",
            ),
            FigureName::Flywheel => (
                BOOK,
                "§35–37 (the piston’s acceleration) with Ng’s T = F · OM, carried over a turn to the fluctuation of energy and the flywheel (docs/dynamics.md §4–5); no figure in either seed",
            ),
            FigureName::Inversion1Engine => {
                (BOOK, "§34, the first inversion of the chain of Fig. 60")
            }
            FigureName::Inversion2RotatingBlock => {
                (BOOK, "§34, the second inversion of the chain of Fig. 60")
            }
            FigureName::Inversion3OscillatingCylinder => {
                (BOOK, "§34, the third inversion of the chain of Fig. 60")
            }
            FigureName::Inversion4HandPump => {
                (BOOK, "§34, the fourth inversion of the chain of Fig. 60")
            }
            FigureName::SlotConvergence => (
                BOOK,
                "§34, Fig. 60 (b) against (c): the curved slot tending to the straight one; no figure in the chapter",
            ),
        };
        format!("{seed}, {place}")
    }

    /// What it shows, in a sentence or two, at the seed's own parameters.
    pub fn description(&self) -> &'static str {
        match self {
            FigureName::Fig62Displacement => {
                "The engine of §35 (r = 0.5 ft, l = 3 ft) at 40°: the crank angle θ, the displacement x of the cross-head A from mid-stroke, the stroke."
            }
            FigureName::Fig63Velocity => {
                "At 30°: D where CB produced meets the perpendicular to the stroke at A, E where the rod produced meets the perpendicular through C; the similar triangles ADB and ECB, CE the piston’s velocity to the scale of CB."
            }
            FigureName::Fig65Klein => {
                "At 30°: CF parallel to DE, FG perpendicular to AB, G on the line through C; CG the piston’s acceleration to the scale ω², in an enlarged detail."
            }
            FigureName::Fig66Kisch => {
                "At 60°: the semicircle on AB, the arc about B through E cutting it at H, HFG perpendicular to AB; D is not needed."
            }
            FigureName::Fig67Example => {
                "The engine of §35 at 45° with the velocity and Kisch’s construction and their scales: CB represents V_c = rω, CE the piston’s velocity, CG its acceleration."
            }
            FigureName::NgFig1Torque => {
                "Ng’s rig (r = 25 mm, l = 72 mm) at 60°: OM, the crank torque T, the slider force F_p = T/OM, the side thrust F_s and the transmission angle β."
            }
            FigureName::NgFigA1Velocity => {
                "At 40°, in Ng’s letters: I, the rod’s instantaneous centre, and M, with the triangles PIC and OCM."
            }
            FigureName::Fig61Centrodes => {
                "The rod’s fixed centrode (full) and moving centrode (dotted, carried with the rod at 35°), touching at D; drawn with n = 2.5, on which the two are far enough apart to read."
            }
            FigureName::Fig64VelocityDiagrams => {
                "At 50°: the polar diagram of piston velocity (CE′ = CE on the crank), the velocity on a distance base and on a time base against simple harmonic motion."
            }
            FigureName::AccelerationDiagrams => {
                "The piston’s acceleration on a distance base and a time base against simple harmonic motion, and the polar diagram CG′ = CG on the crank."
            }
            FigureName::RodMotion => {
                "The rod’s angular velocity and acceleration against θ at 250 rpm, eq. (2a) dashed, the values at 45° marked."
            }
            FigureName::ApproximationError => {
                "The textbook’s approximations less the exact values for n = 4, 5 and 6, scaled: the error due to obliquity, eqs. (2), (3) and (2a)."
            }
            FigureName::CouplerCurves => {
                "The ovals traced by the rod’s points at ¼, ½ and ¾ of AB from A, on the mechanism at 40°."
            }
            FigureName::NgFig2Incline => {
                "The block on a plane tilted at 45°: its weight, the normal force N and the friction μN, so μ = tan 45° = 1."
            }
            FigureName::NgFig7Calibration => {
                "Table 1’s calibration points, the fits through the origin and with an intercept, R² about zero (Ng’s 0.9998) and about the mean."
            }
            FigureName::NgFig8Forces => {
                "F and F′ against θ for T = 264.87 N·mm and μ = 1, the measured F′, the least F and the transmission angle."
            }
            FigureName::CurveBenchmark => {
                "Segments and time against the measured error of the cubic, adaptive-polyline and uniform methods, log–log."
            }
            FigureName::Fig60Chains => {
                "(a) The quadric crank chain, (b) the block in a curved slot about O_cd, (c) the straight slot with O_cd at infinity; links a, b, c, d at 50°."
            }
            FigureName::Inversion1Engine => {
                "The frame d fixed (the direct-acting engine) at 60°: the six virtual centres, O_bd and O_ac by Kennedy’s lines, O_cd at infinity."
            }
            FigureName::Inversion2RotatingBlock => {
                "The crank a fixed (Whitworth’s quick return, the Gnome engine): the slotted frame turning about C, the rod about B."
            }
            FigureName::Inversion3OscillatingCylinder => {
                "The rod b fixed (the oscillating cylinder, the crank and slotted lever): the block swinging about A, the quick return’s time ratio."
            }
            FigureName::Inversion4HandPump => {
                "The block c fixed (the hand pump): the plunger sliding in the fixed barrel, the handle swinging about A."
            }
            FigureName::TurningMoment => {
                "The §35 engine at 250 rpm with a 10 slug reciprocating mass and a steam indicator diagram: the torque on the crank against θ, its mean line and the areas between them, and the energy stored in the flywheel with its fluctuation ΔE."
            }
            FigureName::InertiaForce => {
                "The §35 engine at 30° and 250 rpm with a 10 slug reciprocating mass: Klein’s construction, CG read as the inertia force m ω² CG and drawn at the cross-head against the acceleration; the force resolved along the rod and on the guides; the crank effort T = F · OM through Ng’s OM (= CE)."
            }
            FigureName::PrimarySecondary => {
                "The §35 engine at 250 rpm with a 10 slug reciprocating mass: the primary force m r ω² cos θ, the secondary m r ω² cos 2θ / n, their sum and the exact inertia force against θ, and the exact force less the two terms."
            }
            FigureName::DirectReverseCranks => {
                "The §35 engine at 30° and 250 rpm with a 10 slug reciprocating mass: the primary force as the resultant of the direct and reverse cranks at ±θ, each carrying m/2 at r, the secondary as that of cranks at ±2θ, each m/2 at r/4n turning at 2ω, and the two on the line of stroke against the exact inertia force."
            }
            FigureName::Flywheel => {
                "The turning-moment figure’s engine: the energy stored above its least over the turn, rising by ΔE, and the crank speed with the flywheel I = ΔE/(ω² C_s) for C_s = 0.02, between ω_min and ω_max."
            }
            FigureName::SlotConvergence => {
                "The block in a slot of radius ρ against the straight slot: the largest differences of position, velocity and acceleration for ρ = 1 to 10¹⁵, log–log."
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_figure_names_its_seed_and_section() {
        for f in FigureName::ALL {
            let source = f.source();
            let seed = source.starts_with(BOOK) && source.contains('§')
                || source.starts_with(NG) && source.contains("Fig. ");
            assert!(
                seed || f == FigureName::CurveBenchmark,
                "{}: {source}",
                f.name()
            );
            assert!(!f.description().is_empty());
        }
    }
}
