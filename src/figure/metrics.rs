//! A face's vertical metrics: what the glyph table records of each style
//! and the font reports, apart from both so that the table (written from
//! the faces) and the font (reading the table) do not depend on each other.

/// A face's vertical metrics, in ems (multiply by the font size).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VerticalMetrics {
    /// Height of the ascender line above the baseline.
    pub ascent: f64,
    /// Depth of the descender line below the baseline (positive).
    pub descent: f64,
    /// Height of flat capitals above the baseline.
    pub cap_height: f64,
}
