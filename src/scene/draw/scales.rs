//! The scales layer: notes that say what each constructed length represents
//! (§36: "CB represents V_c", the acceleration scale n²).

use super::LayerCtx;
use crate::figure::RichText;
use crate::geom::Intersection;
use crate::number::{short, sig};
use crate::scene::Layer;
use crate::scene::notation::Named::*;

pub(crate) fn notes(ctx: &LayerCtx) -> Vec<RichText> {
    let scene = ctx.scene;
    let pose = ctx.main.pose();
    let r = pose.mechanism().crank();
    let w = scene.omega().abs();
    let u = scene.units().length();
    let l = |n| ctx.letter(n);
    let (c, b, e) = (l(CrankCentre), l(CrankPin), l(VelocityPoint));
    let v = scene.notation().velocity();
    let mut out = vec![RichText::parse(&format!(
        "Velocity scale: *{c}{b}* = {} {u} represents *{v}*_c = *r*ω = {} {u}/s, so 1 {u} = {} {u}/s.",
        short(r),
        sig(r * w),
        sig(w)
    ))];
    let uses_e = scene.layers().iter().any(|l| l.draws_e());
    if uses_e {
        let ce = ctx.main.e().ce();
        let speed = w * ce.abs();
        let dir = if speed == 0.0 {
            String::from(" (dead centre: at rest)")
        } else if scene.omega() * ce > 0.0 {
            format!(", towards *{c}*")
        } else {
            format!(", away from *{c}*")
        };
        out.push(RichText::parse(&format!(
            "*{c}{e}* = {} {u} represents the piston velocity *{v}*_p = {} {u}/s{dir}.",
            sig(ce.abs()),
            sig(speed)
        )));
    }
    let acceleration = if scene.has(Layer::Kisch) {
        Some(*ctx.main.kisch().points())
    } else if scene.has(Layer::Klein) {
        ctx.main.klein().map(|k| *k.points())
    } else if scene.has(Layer::Ritterhaus) {
        Some(*ctx.main.ritterhaus().points())
    } else if scene.has(Layer::Bennett) {
        ctx.main.bennett().map(|b| *b.points())
    } else {
        None
    };
    if let Some(p) = acceleration {
        let g = l(G);
        let cg = p.cg();
        // The acceleration is ω² CG directed from G towards C.
        let dir = if cg == 0.0 {
            String::new()
        } else {
            format!(", from *{g}* towards *{c}*")
        };
        out.push(RichText::parse(&format!(
            "Acceleration scale: 1 {u} = ({})² {u}/s² = {} {u}/s²;",
            sig(w),
            sig(w * w),
        )));
        out.push(RichText::parse(&format!(
            "*{c}{g}* = {} {u} represents the piston acceleration {} {u}/s²{dir}.",
            sig(cg.abs()),
            sig(w * w * cg.abs())
        )));
    }
    if scene.has(Layer::Velocity)
        && let Intersection::Point(d) = ctx.main.d().d()
    {
        let bd = (d - pose.b()).norm();
        if bd > 0.0 {
            out.push(RichText::parse(&format!(
                "Rod: angular velocity *{v}*_c / *{b}{}* = {} rad/s.",
                l(InstantCentre),
                sig(r * w / bd)
            )));
        }
    }
    out
}
