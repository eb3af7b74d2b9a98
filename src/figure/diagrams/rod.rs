//! Placeholder.

use super::Ctx;
use crate::error::{Error, Result};
use crate::figure::Figure;

pub(super) fn build(ctx: &Ctx) -> Result<Figure> {
    Err(Error::Parse(format!(
        "{} is not drawn yet",
        ctx.name.name()
    )))
}
