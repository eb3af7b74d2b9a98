//! SVG to vector PDF, the text set in the bundled faces and embedded as
//! font subsets (so a PDF reader shows, searches and copies the letters).
//!
//! The SVG is read by usvg, with the same font database as PNG output,
//! into a tree of paths and positioned glyphs; that tree is written as one
//! PDF page with pdf-writer, each face used embedded once as a subset
//! (subsetter) with a ToUnicode map. It covers what the figure writer
//! emits: groups with transforms, clip paths, paths with solid fills and
//! strokes (dashes, caps, joins, opacity) and text. Gradients, patterns,
//! images, masks, filters and group opacity are refused with an error,
//! never drawn wrong.
//!
//! The same SVG gives the same bytes: no date, objects in a fixed order,
//! subset tags derived from the glyphs used.

use super::svg_tree::read;
use crate::error::{Error, Input, Result};
use pdf_writer::types::{
    CidFontType, FontFlags, LineCapStyle, LineJoinStyle, SystemInfo, UnicodeCmap,
};
use pdf_writer::writers::WMode;
use pdf_writer::{Content, Filter, Finish, Name, Pdf, Rect, Ref, Str, TextStr};
use skrifa::instance::{LocationRef, Size};
use skrifa::metrics::Metrics;
use skrifa::string::StringId;
use skrifa::{FontRef, GlyphId, MetadataProvider, Tag};
use std::collections::BTreeMap;
use std::sync::Arc;
use subsetter::GlyphRemapper;
use usvg::fontdb::{Database, ID};
use usvg::tiny_skia_path::{PathSegment, Point};
use usvg::{Group, Node, Paint, Transform};

/// Points (1/72 in) per SVG user unit: the CSS pixel, 96 to the inch, so
/// a figure 760 units wide is a page 570 pt (7.9 in) wide.
pub const POINTS_PER_UNIT: f32 = 0.75;

const CFF: Tag = Tag::new(b"CFF ");
const IDENTITY_H: &str = "Identity-H";
const SYSTEM_INFO: SystemInfo = SystemInfo {
    registry: Str(b"Adobe"),
    ordering: Str(b"Identity"),
    supplement: 0,
};

/// Renders SVG text to the bytes of a one-page vector PDF, the page the
/// SVG's size at [`POINTS_PER_UNIT`]. Letters are set in the bundled
/// faces ([`crate::figure::Font`]) whatever fonts the machine has, and embedded.
///
/// Errors: SVG that cannot be read, and what the PDF writer does not draw
/// ([`Error::Unsupported`]: gradients, patterns, images, masks, filters,
/// group opacity, stroked text).
pub fn to_pdf(svg: &str) -> Result<Vec<u8>> {
    tree_to_pdf(&read(svg)?)
}

/// The PDF of an SVG already read ([`super::svg_tree::read`]): the same
/// bytes as [`to_pdf`] of its text.
pub(crate) fn tree_to_pdf(tree: &usvg::Tree) -> Result<Vec<u8>> {
    let size = tree.size();
    let (width, height) = (
        size.width() * POINTS_PER_UNIT,
        size.height() * POINTS_PER_UNIT,
    );
    let mut page = Page {
        db: tree.fontdb().clone(),
        faces: Vec::new(),
        alphas: Vec::new(),
    };
    let mut content = Content::new();
    // SVG's y runs down the page, PDF's up.
    content.transform([POINTS_PER_UNIT, 0.0, 0.0, -POINTS_PER_UNIT, 0.0, height]);
    page.group(tree.root(), &mut content)?;
    page.write(content.finish().to_vec(), width, height)
}

fn unsupported(what: &str) -> Error {
    Error::Unsupported(format!(
        "PDF output does not draw {what}: write SVG or PNG instead"
    ))
}

/// One face used on the page: the glyphs drawn and the text they stand for.
struct FaceUse {
    id: ID,
    units_per_em: f32,
    remapper: GlyphRemapper,
    /// Old glyph id to the text it was shaped from (for ToUnicode).
    text: BTreeMap<u16, String>,
}

/// What the content stream refers to: faces and opacities.
struct Page {
    /// The faces the tree was laid out with.
    db: Arc<Database>,
    faces: Vec<FaceUse>,
    /// (fill alpha, stroke alpha) of each graphics state, named `G0`, …
    alphas: Vec<(f32, f32)>,
}

impl Page {
    fn group(&mut self, group: &Group, c: &mut Content) -> Result<()> {
        if !group.filters().is_empty() {
            return Err(unsupported("filters"));
        }
        if group.mask().is_some() {
            return Err(unsupported("masks"));
        }
        if group.opacity().get() < 1.0 {
            return Err(unsupported("group opacity"));
        }
        c.save_state();
        if !group.transform().is_identity() {
            c.transform(matrix(group.transform()));
        }
        if let Some(clip) = group.clip_path() {
            if clip.clip_path().is_some() {
                return Err(unsupported("a clip path that is itself clipped"));
            }
            let mut any = false;
            outline_clip(clip.root(), clip.transform(), c, &mut any)?;
            if !any {
                // Clipped to nothing: draw nothing.
                c.restore_state();
                return Ok(());
            }
            c.clip_nonzero();
            c.end_path();
        }
        for child in group.children() {
            match child {
                Node::Group(g) => self.group(g, c)?,
                Node::Path(p) => self.path(p, c)?,
                Node::Text(t) => self.text(t, c)?,
                Node::Image(_) => return Err(unsupported("images")),
            }
        }
        c.restore_state();
        Ok(())
    }

    fn path(&mut self, path: &usvg::Path, c: &mut Content) -> Result<()> {
        if !path.is_visible() {
            return Ok(());
        }
        let fill_first = path.paint_order() == usvg::PaintOrder::FillAndStroke;
        if fill_first && let Some(fill) = path.fill() {
            self.fill(fill, path.data(), c)?;
        }
        if let Some(stroke) = path.stroke() {
            self.stroke(stroke, path.data(), c)?;
        }
        if !fill_first && let Some(fill) = path.fill() {
            self.fill(fill, path.data(), c)?;
        }
        Ok(())
    }

    fn fill(
        &mut self,
        fill: &usvg::Fill,
        data: &usvg::tiny_skia_path::Path,
        c: &mut Content,
    ) -> Result<()> {
        let [r, g, b] = colour(fill.paint())?;
        c.save_state();
        self.alpha(fill.opacity().get(), 1.0, c);
        c.set_fill_rgb(r, g, b);
        outline(data, Transform::identity(), c);
        match fill.rule() {
            usvg::FillRule::NonZero => c.fill_nonzero(),
            usvg::FillRule::EvenOdd => c.fill_even_odd(),
        };
        c.restore_state();
        Ok(())
    }

    fn stroke(
        &mut self,
        stroke: &usvg::Stroke,
        data: &usvg::tiny_skia_path::Path,
        c: &mut Content,
    ) -> Result<()> {
        let [r, g, b] = colour(stroke.paint())?;
        c.save_state();
        self.alpha(1.0, stroke.opacity().get(), c);
        c.set_stroke_rgb(r, g, b);
        c.set_line_width(stroke.width().get());
        c.set_line_cap(match stroke.linecap() {
            usvg::LineCap::Butt => LineCapStyle::ButtCap,
            usvg::LineCap::Round => LineCapStyle::RoundCap,
            usvg::LineCap::Square => LineCapStyle::ProjectingSquareCap,
        });
        c.set_line_join(match stroke.linejoin() {
            usvg::LineJoin::Miter | usvg::LineJoin::MiterClip => LineJoinStyle::MiterJoin,
            usvg::LineJoin::Round => LineJoinStyle::RoundJoin,
            usvg::LineJoin::Bevel => LineJoinStyle::BevelJoin,
        });
        c.set_miter_limit(stroke.miterlimit().get());
        if let Some(dashes) = stroke.dasharray() {
            c.set_dash_pattern(dashes.iter().copied(), stroke.dashoffset());
        }
        outline(data, Transform::identity(), c);
        c.stroke();
        c.restore_state();
        Ok(())
    }

    /// Sets the fill and stroke opacity (a graphics state) unless both are
    /// 1.
    fn alpha(&mut self, fill: f32, stroke: f32, c: &mut Content) {
        if fill >= 1.0 && stroke >= 1.0 {
            return;
        }
        let key = (fill, stroke);
        let index = match self.alphas.iter().position(|a| *a == key) {
            Some(i) => i,
            None => {
                self.alphas.push(key);
                self.alphas.len() - 1
            }
        };
        c.set_parameters(Name(format!("G{index}").as_bytes()));
    }

    fn text(&mut self, text: &usvg::Text, c: &mut Content) -> Result<()> {
        for span in text.layouted() {
            if !span.visible {
                continue;
            }
            for line in [&span.underline, &span.overline].into_iter().flatten() {
                self.path(line, c)?;
            }
            if span.stroke.is_some() {
                return Err(unsupported("stroked text"));
            }
            if let Some(fill) = &span.fill {
                let [r, g, b] = colour(fill.paint())?;
                c.save_state();
                self.alpha(fill.opacity().get(), 1.0, c);
                c.set_fill_rgb(r, g, b);
                c.begin_text();
                let size = span.font_size.get();
                let mut current = None;
                for glyph in &span.positioned_glyphs {
                    let index = self.face(glyph.font)?;
                    if current != Some(index) {
                        c.set_font(Name(format!("F{index}").as_bytes()), size);
                        current = Some(index);
                    }
                    // cannot fail: `face` gives a position in `faces` (one
                    // found there or the one it pushed), which only grow.
                    #[allow(clippy::indexing_slicing)]
                    let face = &mut self.faces[index];
                    let old = u16::try_from(glyph.id.0)
                        .map_err(|_| Error::Limit("a glyph id beyond 65535".into()))?;
                    let cid = face.remapper.remap(old);
                    face.text.entry(old).or_insert_with(|| glyph.text.clone());
                    let upem = face.units_per_em;
                    // The glyph's transform is scaled to the font size;
                    // the PDF text matrix wants font units at size 1.
                    let ts = glyph
                        .outline_transform()
                        .pre_scale(upem, upem)
                        .pre_scale(1.0 / size, 1.0 / size);
                    c.set_text_matrix(matrix(ts));
                    c.show(Str(&cid.to_be_bytes()));
                }
                c.end_text();
                c.restore_state();
            }
            if let Some(line) = &span.line_through {
                self.path(line, c)?;
            }
        }
        Ok(())
    }

    /// The index of face `id` among those used, added when new.
    fn face(&mut self, id: ID) -> Result<usize> {
        if let Some(i) = self.faces.iter().position(|f| f.id == id) {
            return Ok(i);
        }
        let units_per_em = self
            .db
            .with_face_data(id, |data, index| {
                FontRef::from_index(data, index).ok().map(|f| {
                    f.metrics(Size::unscaled(), LocationRef::default())
                        .units_per_em
                })
            })
            .flatten()
            .ok_or_else(|| Error::invalid(Input::Svg, "a face of the SVG cannot be read".into()))?;
        self.faces.push(FaceUse {
            id,
            units_per_em: f32::from(units_per_em),
            remapper: GlyphRemapper::new(),
            text: BTreeMap::new(),
        });
        Ok(self.faces.len() - 1)
    }

    /// The document: catalogue, page tree, the page and its resources,
    /// then each face.
    fn write(self, content: Vec<u8>, width: f32, height: f32) -> Result<Vec<u8>> {
        let mut next = 1;
        let mut alloc = || {
            let r = Ref::new(next);
            next += 1;
            r
        };
        let (catalog, pages, page, contents, info) = (alloc(), alloc(), alloc(), alloc(), alloc());
        let faces: Vec<Ref> = self.faces.iter().map(|_| alloc()).collect();
        let states: Vec<Ref> = self.alphas.iter().map(|_| alloc()).collect();
        let mut pdf = Pdf::new();
        pdf.catalog(catalog).pages(pages);
        pdf.pages(pages).kids([page]).count(1);
        {
            let mut p = pdf.page(page);
            p.parent(pages)
                .media_box(Rect::new(0.0, 0.0, width, height))
                .contents(contents);
            let mut resources = p.resources();
            let mut fonts = resources.fonts();
            for (i, r) in faces.iter().enumerate() {
                fonts.pair(Name(format!("F{i}").as_bytes()), *r);
            }
            fonts.finish();
            let mut gs = resources.ext_g_states();
            for (i, r) in states.iter().enumerate() {
                gs.pair(Name(format!("G{i}").as_bytes()), *r);
            }
        }
        pdf.stream(contents, &deflate(&content)?)
            .filter(Filter::FlateDecode);
        pdf.document_info(info)
            .producer(TextStr(concat!("slider-crank ", env!("CARGO_PKG_VERSION"))));
        for (r, &(fill, stroke)) in states.iter().zip(&self.alphas) {
            pdf.ext_graphics(*r)
                .non_stroking_alpha(fill)
                .stroking_alpha(stroke);
        }
        for (face, type0) in self.faces.iter().zip(faces) {
            let refs = [alloc(), alloc(), alloc(), alloc()];
            self.db
                .with_face_data(face.id, |data, index| {
                    write_face(&mut pdf, face, type0, refs, data, index)
                })
                .unwrap_or_else(|| {
                    Err(Error::invalid(
                        Input::Svg,
                        "a face of the SVG cannot be read".into(),
                    ))
                })?;
        }
        Ok(pdf.finish())
    }
}

/// Writes one face as a Type 0 font with Identity-H encoding: the CID
/// font, its descriptor, the ToUnicode map and the embedded subset (CIDs
/// are the subset's glyph ids).
fn write_face(
    pdf: &mut Pdf,
    face: &FaceUse,
    type0: Ref,
    [cid_ref, descriptor, cmap, file]: [Ref; 4],
    data: &[u8],
    index: u32,
) -> Result<()> {
    let font = FontRef::from_index(data, index).map_err(|_| bad_face())?;
    let cff = font.table_data(CFF).is_some();
    let postscript = font
        .localized_strings(StringId::POSTSCRIPT_NAME)
        .english_or_first()
        .map(|s| s.to_string())
        .unwrap_or_else(|| "Unknown".into());
    let base = format!("{}+{postscript}", subset_tag(&postscript, &face.remapper));
    let type0_name = if cff {
        format!("{base}-{IDENTITY_H}")
    } else {
        base.clone()
    };
    pdf.type0_font(type0)
        .base_font(Name(type0_name.as_bytes()))
        .encoding_predefined(Name(IDENTITY_H.as_bytes()))
        .descendant_font(cid_ref)
        .to_unicode(cmap);
    let m = font.metrics(Size::unscaled(), LocationRef::default());
    write_cid_font(pdf, face, &font, [cid_ref, descriptor], &base, cff);
    write_descriptor(pdf, &m, [descriptor, file], &base, cff);
    write_to_unicode(pdf, face, cmap);
    write_program(pdf, face, file, data, index, &postscript, cff)
}

/// The error for a bundled face that cannot be read.
fn bad_face() -> Error {
    Error::invalid(Input::Svg, "a bundled face cannot be read".into())
}

/// A length in font units as thousandths of the em, PDF's glyph space.
fn per_mille(v: f32, units_per_em: u16) -> f32 {
    v / f32::from(units_per_em) * 1000.0
}

/// Writes the CID font of a face (`refs`: the CID font and its
/// descriptor): CFF or TrueType outlines, with the advance of each glyph
/// of the subset (0 where the face has none).
fn write_cid_font(
    pdf: &mut Pdf,
    face: &FaceUse,
    font: &FontRef,
    [cid_ref, descriptor]: [Ref; 2],
    base: &str,
    cff: bool,
) {
    let units_per_em = font
        .metrics(Size::unscaled(), LocationRef::default())
        .units_per_em;
    let glyphs = font.glyph_metrics(Size::unscaled(), LocationRef::default());
    let mut cid = pdf.cid_font(cid_ref);
    cid.subtype(if cff {
        CidFontType::Type0
    } else {
        CidFontType::Type2
    });
    cid.base_font(Name(base.as_bytes()));
    cid.system_info(SYSTEM_INFO);
    cid.font_descriptor(descriptor);
    cid.default_width(0.0);
    if !cff {
        cid.cid_to_gid_map_predefined(Name(b"Identity"));
    }
    {
        let mut widths = cid.widths();
        for (new, old) in face.remapper.remapped_gids().enumerate() {
            let advance = glyphs
                .advance_width(GlyphId::new(u32::from(old)))
                .unwrap_or(0.0);
            let new = new as u16;
            widths.same(new, new, per_mille(advance, units_per_em));
        }
    }
    cid.finish();
}

/// Writes the font descriptor of a face (`refs`: the descriptor and the
/// embedded program) from its metrics: flags, box (empty where the face
/// gives none), angle, ascent, descent and cap height (the ascent where
/// the face gives none).
fn write_descriptor(
    pdf: &mut Pdf,
    m: &Metrics,
    [descriptor, file]: [Ref; 2],
    base: &str,
    cff: bool,
) {
    let pm = |v: f32| per_mille(v, m.units_per_em);
    let mut flags = FontFlags::SYMBOLIC;
    flags.set(FontFlags::SERIF, true);
    flags.set(FontFlags::FIXED_PITCH, m.is_monospace);
    flags.set(FontFlags::ITALIC, m.italic_angle != 0.0);
    let bbox = m.bounds.map_or(Rect::new(0.0, 0.0, 0.0, 0.0), |b| {
        Rect::new(pm(b.x_min), pm(b.y_min), pm(b.x_max), pm(b.y_max))
    });
    let mut d = pdf.font_descriptor(descriptor);
    d.name(Name(base.as_bytes()))
        .flags(flags)
        .bbox(bbox)
        .italic_angle(m.italic_angle)
        .ascent(pm(m.ascent))
        .descent(pm(m.descent))
        .cap_height(pm(m.cap_height.unwrap_or(m.ascent)))
        .stem_v(80.0);
    if cff {
        d.font_file3(file);
    } else {
        d.font_file2(file);
    }
    d.finish();
}

/// Writes the ToUnicode map of a face: each glyph of the subset to the
/// text it was shaped from (glyphs shaped from no text are left out).
fn write_to_unicode(pdf: &mut Pdf, face: &FaceUse, cmap: Ref) {
    let mut map = UnicodeCmap::new(Name(b"Custom"), SYSTEM_INFO);
    for (old, text) in &face.text {
        if let Some(new) = face.remapper.get(*old)
            && !text.is_empty()
        {
            map.pair_with_multiple(new, text.chars());
        }
    }
    pdf.cmap(cmap, &map.finish())
        .writing_mode(WMode::Horizontal);
}

/// Writes the subset of a face as a compressed stream: a CFF face as its
/// bare CFF program, any other as the whole subset font. An error where
/// the face cannot be subset.
fn write_program(
    pdf: &mut Pdf,
    face: &FaceUse,
    file: Ref,
    data: &[u8],
    index: u32,
    postscript: &str,
    cff: bool,
) -> Result<()> {
    let subset = subsetter::subset(data, index, &face.remapper)
        .map_err(|e| Error::invalid(Input::Svg, format!("cannot subset {postscript}: {e}")))?;
    let program = if cff {
        let sub = skrifa::raw::FontRef::new(&subset).map_err(|_| bad_face())?;
        sub.table_data(CFF)
            .ok_or_else(bad_face)?
            .as_bytes()
            .to_vec()
    } else {
        subset
    };
    let compressed = deflate(&program)?;
    let mut stream = pdf.stream(file, &compressed);
    stream.filter(Filter::FlateDecode);
    if cff {
        stream.pair(Name(b"Subtype"), Name(b"CIDFontType0C"));
    }
    stream.finish();
    Ok(())
}

/// The six-letter tag that marks a subset: from its face's name and
/// glyphs (FNV-1a, so the same glyphs give the same tag on every build).
fn subset_tag(name: &str, remapper: &GlyphRemapper) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let bytes = name
        .bytes()
        .chain(remapper.remapped_gids().flat_map(u16::to_be_bytes));
    for b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    (0..6)
        .map(|_| {
            let letter = (b'A' + (h % 26) as u8) as char;
            h /= 26;
            letter
        })
        .collect()
}

fn colour(paint: &Paint) -> Result<[f32; 3]> {
    match paint {
        Paint::Color(c) => Ok([c.red, c.green, c.blue].map(|v| f32::from(v) / 255.0)),
        _ => Err(unsupported("gradients or patterns")),
    }
}

fn matrix(t: Transform) -> [f32; 6] {
    [t.sx, t.ky, t.kx, t.sy, t.tx, t.ty]
}

/// Appends the path's segments, mapped by `t`, to the content stream
/// (quadratic segments as the equal cubics).
fn outline(path: &usvg::tiny_skia_path::Path, t: Transform, c: &mut Content) {
    let map = |mut p: Point| {
        t.map_point(&mut p);
        p
    };
    let mut last = Point::zero();
    for segment in path.segments() {
        match segment {
            PathSegment::MoveTo(p) => {
                let q = map(p);
                c.move_to(q.x, q.y);
                last = p;
            }
            PathSegment::LineTo(p) => {
                let q = map(p);
                c.line_to(q.x, q.y);
                last = p;
            }
            PathSegment::QuadTo(p1, p) => {
                let c1 = Point::from_xy(
                    last.x + 2.0 / 3.0 * (p1.x - last.x),
                    last.y + 2.0 / 3.0 * (p1.y - last.y),
                );
                let c2 = Point::from_xy(
                    p.x + 2.0 / 3.0 * (p1.x - p.x),
                    p.y + 2.0 / 3.0 * (p1.y - p.y),
                );
                let (c1, c2, q) = (map(c1), map(c2), map(p));
                c.cubic_to(c1.x, c1.y, c2.x, c2.y, q.x, q.y);
                last = p;
            }
            PathSegment::CubicTo(p1, p2, p) => {
                let (c1, c2, q) = (map(p1), map(p2), map(p));
                c.cubic_to(c1.x, c1.y, c2.x, c2.y, q.x, q.y);
                last = p;
            }
            PathSegment::Close => {
                c.close_path();
            }
        }
    }
}

/// Appends the outlines of a clip path's shapes (in the group's frame,
/// through `t`) to the content stream.
fn outline_clip(group: &Group, t: Transform, c: &mut Content, any: &mut bool) -> Result<()> {
    let t = t.pre_concat(group.transform());
    for child in group.children() {
        match child {
            Node::Group(g) => outline_clip(g, t, c, any)?,
            Node::Path(p) => {
                outline(p.data(), t, c);
                *any = true;
            }
            Node::Text(_) | Node::Image(_) => return Err(unsupported("text or images as a clip")),
        }
    }
    Ok(())
}

/// A stream's bytes compressed as zlib (`/FlateDecode`) at level 6.
fn deflate(data: &[u8]) -> Result<Vec<u8>> {
    use std::io::Write;
    let mut encoder = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::new(6));
    encoder
        .write_all(data)
        .and_then(|()| encoder.finish())
        .map_err(|e| Error::Io {
            message: format!("cannot compress a PDF stream: {e}"),
            path: None,
            source: None,
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalogue::FigureName;
    use crate::catalogue::FigureOptions;
    use crate::render::to_svg;

    #[test]
    fn a_figure_is_one_page_with_its_faces_embedded() {
        let svg = to_svg(
            &FigureName::Fig67Example
                .figure(&FigureOptions::default())
                .unwrap(),
        );
        let pdf = to_pdf(&svg).unwrap();
        assert!(pdf.starts_with(b"%PDF-"));
        let text = String::from_utf8_lossy(&pdf);
        assert!(text.contains("/MediaBox [0 0 570 "), "page width");
        assert!(text.contains("NewCM10-Italic"), "the italic face");
        assert!(text.contains("/FontFile3"), "embedded");
        assert!(text.contains("/ToUnicode"));
        // The same SVG, the same bytes.
        assert!(to_pdf(&svg).unwrap() == pdf);
    }

    #[test]
    fn what_it_does_not_draw_is_refused() {
        let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10">
            <linearGradient id="g"><stop offset="0" stop-color="red"/><stop offset="1" stop-color="blue"/></linearGradient>
            <rect width="5" height="5" fill="url(#g)"/></svg>"#;
        let err = to_pdf(svg).unwrap_err().to_string();
        assert!(
            err.starts_with("PDF output does not draw gradients"),
            "{err}"
        );
        assert!(matches!(
            to_pdf("<svg"),
            Err(Error::Invalid {
                input: Input::Svg,
                ..
            })
        ));
    }
}
