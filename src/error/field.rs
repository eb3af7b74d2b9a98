//! The parameters an error about a number names, and the fields of a
//! request a message names.

/// Which parameter an [`Error::NotFinite`](super::Error::NotFinite),
/// [`Error::NotPositive`](super::Error::NotPositive),
/// [`Error::Negative`](super::Error::Negative) or
/// [`Error::OutOfRange`](super::Error::OutOfRange) is about, so that a
/// caller tells them apart by kind rather than by text (the command line
/// and the catalogue say "a page too small for its plots" when the field
/// is [`Field::PanelWidth`]), and the field of a request a
/// [`Wording`](super::Wording) names, which each front end writes its
/// own way ([`Field::key`]).
///
/// Its `Display` is the parameter's name as the message writes it
/// (`crank`, `panel width`, `rod-cg`), the name in the library's own
/// words, not a command-line flag. The enum is closed over every
/// parameter the crate checks (a few dozen, each named once here), so a
/// new check adds a variant rather than free text.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Field {
    /// The crank radius r of a mechanism or a quadric chain.
    Crank,
    /// The connecting rod's length l.
    Rod,
    /// The offset e of the line of stroke.
    Offset,
    /// The ratio n = l/r of rod to crank (of a table's rows).
    Ratio,
    /// The coupler b of a quadric chain, or the place of a coupler point
    /// along the rod.
    Coupler,
    /// The lever c of a quadric chain, or the arm of a quick return's
    /// slotted link that drives the tool.
    Lever,
    /// The fixed link d of a quadric chain.
    Frame,
    /// The longest link of a quadric chain (which must be shorter than
    /// the other three together).
    LongestLink,
    /// The radius of a cylindric chain's curved slot.
    SlotRadius,
    /// The size |ρ| of the slot's radius, against the crank it must exceed.
    SlotRadiusSize,
    /// The curvature 1/ρ of the slot.
    SlotCurvature,
    /// The number of an inversion of the chain (1 to 4).
    Inversion,
    /// The four links of a quadric crank chain, given together.
    Links,
    /// The assembly mode of a quadric crank chain.
    Assembly,
    /// The crank speed ω in rad/s.
    Omega,
    /// The crank speed in revolutions per minute.
    Rpm,
    /// A crank angle, or the tilt of Ng's plane, in degrees.
    Angle,
    /// The number of crank angles of a scene.
    Angles,
    /// The number of angles a view is held over.
    HeldAngles,
    /// A torque on the crank.
    Torque,
    /// The force on the slider.
    SliderForce,
    /// A coefficient of friction.
    Friction,
    /// The direction of gravity along a vertical engine's line of stroke.
    Gravity,
    /// The tilt of a plane.
    Tilt,
    /// A tolerance (of a curve, a plot or the cross-check).
    Tolerance,
    /// The number of poses the cross-check samples.
    Samples,
    /// An x value of a line fit.
    X,
    /// A y value of a line fit.
    Y,
    /// The period of an animation's revolution.
    Period,
    /// The number of frames of an animation or a scene.
    Frames,
    /// The lower end of a plot's axis.
    AxisMinimum,
    /// The upper end of a plot's axis.
    AxisMaximum,
    /// The span of a plot's axis.
    AxisRange,
    /// The step between an axis's ticks.
    TickStep,
    /// The start of the range a curve is traced over.
    RangeStart,
    /// The end of the range a curve is traced over.
    RangeEnd,
    /// The number of pieces a curve is traced in.
    Pieces,
    /// The width of a plot's panel (too small a page for the plots).
    PanelWidth,
    /// The world rectangle a plot maps onto its area.
    WorldFrame,
    /// The width of the page.
    PageWidth,
    /// The height of the page.
    PageHeight,
    /// The margin of the page.
    PageMargin,
    /// A length on the page given with its unit (`120mm`).
    PageLength,
    /// The scale of a PNG.
    Scale,
    /// The size of a PNG in pixels.
    PngSize,
    /// The bore D of the cylinder.
    Bore,
    /// A pressure of an indicator diagram.
    Pressure,
    /// A gas force on the piston.
    GasForce,
    /// The reciprocating mass m.
    Mass,
    /// The mass of the connecting rod.
    RodMass,
    /// The distance of the rod's centre of gravity from the crank pin.
    RodCg,
    /// The radius of gyration of the rod.
    RodGyration,
    /// The number of cylinders of an engine.
    Cylinders,
    /// The crank phase of a cylinder.
    Phase,
    /// The distance of a cylinder's line of stroke from the reference
    /// plane along the crank shaft.
    Plane,
    /// The flywheel's moment of inertia.
    Flywheel,
    /// The coefficient of fluctuation of speed C_s.
    FluctuationOfSpeed,
    /// The fluctuation of energy over a turn.
    FluctuationOfEnergy,
    /// The handout's coefficient of fluctuation of speed.
    Fluctuation,
    /// The size of a handout's class.
    Class,
    /// The order of a series: how many harmonics it runs to.
    Order,
    /// The decimals of a table's numbers.
    Decimals,
    /// The fraction of the reciprocating mass a counterweight balances.
    BalancedFraction,
    /// The diameter of a locomotive's wheel.
    Wheel,
    /// A speed along the rails.
    Speed,
    /// A wheel's static load on the rail.
    Load,
    /// The angle of a cylinder's axis about the crank shaft.
    Axis,
    /// The measured data (CSV) a figure draws, or the indicator diagram
    /// of its engine.
    Data,
    /// Which calibration line a figure draws.
    Fit,
    /// The layers of a mechanism figure.
    Layers,
    /// The drawing style.
    Style,
    /// The face of the text.
    Font,
    /// The letters of a mechanism figure.
    Notation,
    /// Whether the mechanism is drawn mirrored.
    Mirror,
    /// The most values one request may compute.
    MaxCells,
    /// The name of the length unit.
    Unit,
    /// The name of the force unit.
    ForceUnit,
    /// The crank angles of an in-line engine's cylinders.
    Cranks,
    /// An engine's own indicator diagram (a handout's).
    Indicator,
    /// The file a figure, a handout or a gallery is written to, which
    /// the names of the files made beside it come from.
    Out,
    /// A gallery's manifest file.
    Manifest,
    /// The figures a gallery is limited to.
    Only,
}

impl Field {
    /// The parameter's name as messages write it (`crank`, `page width`).
    pub fn name(self) -> &'static str {
        match self {
            Field::Crank => "crank",
            Field::Rod => "rod",
            Field::Offset => "offset",
            Field::Ratio => "n",
            Field::Coupler => "coupler",
            Field::Lever => "lever",
            Field::Frame => "frame",
            Field::LongestLink => "longest link",
            Field::SlotRadius => "slot radius",
            Field::SlotRadiusSize => "|slot radius|",
            Field::SlotCurvature => "slot curvature",
            Field::Inversion => "inversion",
            Field::Links => "links",
            Field::Assembly => "assembly",
            Field::Omega => "omega",
            Field::Rpm => "rpm",
            Field::Angle => "angle",
            Field::Angles => "angles",
            Field::HeldAngles => "held angles",
            Field::Torque => "torque",
            Field::SliderForce => "slider force",
            Field::Friction => "friction",
            Field::Gravity => "gravity",
            Field::Tilt => "tilt",
            Field::Tolerance => "tolerance",
            Field::Samples => "samples",
            Field::X => "x",
            Field::Y => "y",
            Field::Period => "period",
            Field::Frames => "frames",
            Field::AxisMinimum => "axis minimum",
            Field::AxisMaximum => "axis maximum",
            Field::AxisRange => "axis range",
            Field::TickStep => "tick step",
            Field::RangeStart => "range start",
            Field::RangeEnd => "range end",
            Field::Pieces => "pieces",
            Field::PanelWidth => "panel width",
            Field::WorldFrame => "world frame",
            Field::PageWidth => "page width",
            Field::PageHeight => "page height",
            Field::PageMargin => "page margin",
            Field::PageLength => "page length",
            Field::Scale => "scale",
            Field::PngSize => "PNG size",
            Field::Bore => "bore",
            Field::Pressure => "pressure",
            Field::GasForce => "gas force",
            Field::Mass => "mass",
            Field::RodMass => "rod mass",
            Field::RodCg => "rod-cg",
            Field::RodGyration => "rod gyration",
            Field::Cylinders => "cylinders",
            Field::Phase => "phase",
            Field::Plane => "plane",
            Field::Flywheel => "flywheel",
            Field::FluctuationOfSpeed => "fluctuation of speed",
            Field::FluctuationOfEnergy => "fluctuation of energy",
            Field::Fluctuation => "fluctuation",
            Field::Class => "class",
            Field::Order => "order",
            Field::Decimals => "decimals",
            Field::BalancedFraction => "fraction",
            Field::Wheel => "wheel",
            Field::Speed => "speed",
            Field::Load => "load",
            Field::Axis => "axis",
            Field::Data => "data",
            Field::Fit => "fit",
            Field::Layers => "layers",
            Field::Style => "style",
            Field::Font => "font",
            Field::Notation => "notation",
            Field::Mirror => "mirror",
            Field::MaxCells => "max cells",
            Field::Unit => "unit",
            Field::ForceUnit => "force unit",
            Field::Cranks => "crank angles",
            Field::Indicator => "indicator",
            Field::Out => "out",
            Field::Manifest => "manifest",
            Field::Only => "only",
        }
    }

    /// The field's key in a request: the Python package's keyword and a
    /// scene file's key (`gas_force`, `max_cells`); the command line's
    /// flag is the key with hyphens for its underscores. A field whose
    /// name is one word is keyed by its name (`crank`, `data`); the
    /// parameters no request gives (a panel's width) are keyed by their
    /// name too, as [`Field::name`] writes it. A field a request gives as
    /// a list is keyed by the list (`planes`, `axes`), its name the one
    /// value a message is about (`plane`).
    pub fn key(self) -> &'static str {
        match self {
            Field::GasForce => "gas_force",
            Field::MaxCells => "max_cells",
            Field::RodCg => "rod_cg",
            Field::SlotRadius => "slot_radius",
            Field::RodMass => "rod_mass",
            Field::RodGyration => "rod_gyration",
            Field::ForceUnit => "force_unit",
            Field::Cranks => "cranks",
            Field::Phase => "phases",
            Field::Plane => "planes",
            Field::BalancedFraction => "fractions",
            Field::Axis => "axes",
            Field::FluctuationOfSpeed | Field::Fluctuation => "fluctuation",
            Field::Ratio => "n",
            other => other.name(),
        }
    }
}

impl std::fmt::Display for Field {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::Field;
    use crate::error::Error;

    #[test]
    fn fields_read_as_the_messages_wrote_them() {
        let e = Error::OutOfRange {
            name: Field::RodCg,
            value: 3.5,
            reason: "the centre of gravity lies on the rod, 0 to 3".into(),
        };
        assert_eq!(
            e.to_string(),
            "rod-cg = 3.5 is out of range: the centre of gravity lies on the rod, 0 to 3"
        );
        let e = Error::NotPositive {
            name: Field::PageWidth,
            value: 0.0,
        };
        assert_eq!(e.to_string(), "page width must be greater than zero, got 0");
        let e = Error::NotFinite {
            name: Field::SlotRadiusSize,
            value: f64::NAN,
        };
        assert_eq!(
            e.to_string(),
            "|slot radius| must be a finite number, got NaN"
        );
        assert_eq!(Field::PngSize.to_string(), "PNG size");
        // The library's own checks, as the command line printed them.
        let e = crate::mechanism::SliderCrank::new(0.0, 3.0, 0.0).unwrap_err();
        assert!(
            matches!(
                e,
                Error::NotPositive {
                    name: Field::Crank,
                    ..
                }
            ),
            "{e:?}"
        );
        assert_eq!(e.to_string(), "crank must be greater than zero, got 0");
        let e = crate::scene::Page::new(10.0, 600.0, 0.0).unwrap_err();
        assert!(
            matches!(
                e,
                Error::OutOfRange {
                    name: Field::PageWidth,
                    ..
                }
            ),
            "{e:?}"
        );
        assert_eq!(
            e.to_string(),
            "page width = 10 is out of range: a page is between 50 and 20000 units (px, 96 to the inch: 13.3 mm to 5.29 m)"
        );
        assert_eq!(
            Field::FluctuationOfSpeed.to_string(),
            "fluctuation of speed"
        );
    }
}
