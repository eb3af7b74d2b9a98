//! SVG elements as a small tree written straight into one string.
//!
//! The figures' elements are many (a plate has hundreds) and their
//! attributes few, so an element keeps its attributes in a short vector
//! sorted by name as they are set, and writes itself with one pass of
//! escaping into the document's buffer: no map, no per-element sort, no
//! string per escaped value. The bytes are those of the `svg` crate's
//! writer the figures were first written with (attributes in name order;
//! a line break before and after each child element, none around text),
//! so every written figure stayed byte for byte the same.

use std::borrow::Cow;

/// An attribute's value: borrowed where it is a constant (`"none"`, a
/// colour), owned where it was formatted.
pub(crate) type Value = Cow<'static, str>;

/// A child of an element.
#[derive(Debug, Clone)]
pub(crate) enum Node {
    /// An element, written on its own line.
    Element(Element),
    /// Character data, escaped as it is written, on the element's line.
    Text(String),
    /// Markup written as it is (the `<tspan>` runs of a text), on the
    /// element's line.
    Raw(String),
    /// Markup written as it is on lines of its own (an animation's
    /// frame, a whole figure).
    Block(String),
}

/// An SVG element: its name, its attributes sorted by name, its children
/// in order. An element without children is written self-closed.
#[derive(Debug, Clone)]
pub(crate) struct Element {
    name: &'static str,
    attributes: Vec<(&'static str, Value)>,
    children: Vec<Node>,
}

impl Element {
    /// An element `name` without attributes or children.
    pub(crate) fn new(name: &'static str) -> Self {
        Element {
            name,
            attributes: Vec::new(),
            children: Vec::new(),
        }
    }

    /// An element `name` holding only the character data `text` (a
    /// `<title>`, a `<metadata>`), written on its line.
    pub(crate) fn text(name: &'static str, text: String) -> Self {
        Element::new(name).add(Node::Text(text))
    }

    /// The root `<svg>` element with its namespace.
    pub(crate) fn document() -> Self {
        Element::new("svg").set("xmlns", "http://www.w3.org/2000/svg")
    }

    /// The element with attribute `name` set to `value` (replacing a value
    /// set before).
    pub(crate) fn set(mut self, name: &'static str, value: impl Into<Value>) -> Self {
        self.assign(name, value);
        self
    }

    /// Sets attribute `name` to `value`, replacing a value set before.
    pub(crate) fn assign(&mut self, name: &'static str, value: impl Into<Value>) {
        let value = value.into();
        match self.attributes.binary_search_by(|(k, _)| k.cmp(&name)) {
            Ok(i) => {
                if let Some((_, old)) = self.attributes.get_mut(i) {
                    *old = value;
                }
            }
            Err(i) => self.attributes.insert(i, (name, value)),
        }
    }

    /// The element with `child` appended.
    pub(crate) fn add(mut self, child: impl Into<Node>) -> Self {
        self.append(child);
        self
    }

    /// Appends `child`.
    pub(crate) fn append(&mut self, child: impl Into<Node>) {
        self.children.push(child.into());
    }

    /// Every `id` of the element and its descendants made to start with
    /// `prefix`, and every reference to one (`url(#…)` in a value,
    /// `href="#…"`); text and markup held as text are left alone.
    pub(crate) fn prefix_ids(&mut self, prefix: &str) {
        for (name, value) in &mut self.attributes {
            let prefixed = match *name {
                "id" => Some(format!("{prefix}{value}")),
                "href" | "xlink:href" => value
                    .strip_prefix('#')
                    .map(|rest| format!("#{prefix}{rest}")),
                _ if value.contains("url(#") => {
                    Some(value.replace("url(#", &format!("url(#{prefix}")))
                }
                _ => None,
            };
            if let Some(v) = prefixed {
                *value = Value::Owned(v);
            }
        }
        for child in &mut self.children {
            if let Node::Element(e) = child {
                e.prefix_ids(prefix);
            }
        }
    }

    /// The element's children as the document writes them, without the
    /// element's own tags: one to a line, no line break before the first
    /// or after the last.
    pub(crate) fn children_text(&self) -> String {
        let mut out = String::with_capacity(1 << 16);
        for (i, child) in self.children.iter().enumerate() {
            if i > 0 {
                out.push('\n');
            }
            match child {
                Node::Element(e) => e.write(&mut out, false),
                Node::Text(t) => escape_into(&mut out, t, false),
                Node::Raw(r) | Node::Block(r) => out.push_str(r),
            }
        }
        out
    }

    /// The element as a document: every child on its own line, the
    /// whole ended by a line break.
    pub(crate) fn to_document(&self) -> String {
        let mut out = String::with_capacity(1 << 16);
        self.write(&mut out, true);
        out.push('\n');
        out
    }

    /// Writes the element into `out`. With `lines`, every child takes its
    /// own line, text too (the root); otherwise text and raw markup stay
    /// on the element's line.
    fn write(&self, out: &mut String, lines: bool) {
        out.push('<');
        out.push_str(self.name);
        for (name, value) in &self.attributes {
            out.push(' ');
            out.push_str(name);
            out.push_str("=\"");
            escape_into(out, value, true);
            out.push('"');
        }
        if self.children.is_empty() {
            out.push_str("/>");
            return;
        }
        out.push('>');
        let mut bare = false;
        for child in &self.children {
            bare = !lines && matches!(child, Node::Text(_) | Node::Raw(_));
            if !bare {
                out.push('\n');
            }
            match child {
                Node::Element(e) => e.write(out, false),
                Node::Text(t) => escape_into(out, t, false),
                Node::Raw(r) | Node::Block(r) => out.push_str(r),
            }
        }
        if !bare {
            out.push('\n');
        }
        out.push_str("</");
        out.push_str(self.name);
        out.push('>');
    }
}

impl std::fmt::Display for Element {
    /// The element as written inside another (text on its line).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let mut out = String::new();
        self.write(&mut out, false);
        f.write_str(&out)
    }
}

impl From<Element> for Node {
    fn from(e: Element) -> Self {
        Node::Element(e)
    }
}

/// `s` as character data: `&`, `<` and `>` escaped.
pub(crate) fn escape_text(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    escape_into(&mut out, s, false);
    out
}

/// `s` appended to `out` with `&`, `<`, `>` escaped, and in an attribute
/// (`quotes`) `"` and `'` too.
fn escape_into(out: &mut String, s: &str, quotes: bool) {
    let mut rest = s;
    while let Some(i) = rest.find(['&', '<', '>', '"', '\'']) {
        let (head, tail) = rest.split_at(i);
        out.push_str(head);
        let mut chars = tail.chars();
        out.push_str(match chars.next() {
            Some('&') => "&amp;",
            Some('<') => "&lt;",
            Some('>') => "&gt;",
            Some('"') if quotes => "&quot;",
            Some('\'') if quotes => "&apos;",
            Some('"') => "\"",
            _ => "'",
        });
        rest = chars.as_str();
    }
    out.push_str(rest);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_and_references_are_prefixed_in_attributes_only() {
        let mut root = Element::new("svg")
            .add(Element::text("title", "id=\"x\" url(#y)".into()))
            .add(
                Element::new("g")
                    .set("id", "a")
                    .set("clip-path", "url(#c)")
                    .add(Element::new("use").set("href", "#a"))
                    .add(Element::new("use").set("href", "other.svg#a")),
            );
        root.prefix_ids("f001-");
        assert_eq!(
            root.children_text(),
            "<title>id=\"x\" url(#y)</title>\n<g clip-path=\"url(#f001-c)\" id=\"f001-a\">\n<use href=\"#f001-a\"/>\n<use href=\"other.svg#a\"/>\n</g>"
        );
    }

    #[test]
    fn attributes_are_written_in_name_order_and_escaped() {
        let e = Element::new("path")
            .set("stroke", "#000")
            .set("d", String::from("M0 0"))
            .set("id", "a<b>&\"c'");
        let mut out = String::new();
        e.write(&mut out, false);
        assert_eq!(
            out,
            r##"<path d="M0 0" id="a&lt;b&gt;&amp;&quot;c&apos;" stroke="#000"/>"##
        );
    }

    #[test]
    fn a_value_set_again_replaces_the_first() {
        let e = Element::new("g").set("fill", "none").set("fill", "red");
        let mut out = String::new();
        e.write(&mut out, false);
        assert_eq!(out, r#"<g fill="red"/>"#);
    }

    #[test]
    fn child_elements_take_their_own_lines_and_text_does_not() {
        let text = Element::new("text").add(Node::Raw("<tspan>x</tspan>".into()));
        let title = Element::new("title").add(Node::Text("a < b 'c'".into()));
        let g = Element::new("g").add(text).add(title);
        let mut out = String::new();
        g.write(&mut out, false);
        assert_eq!(
            out,
            "<g>\n<text><tspan>x</tspan></text>\n<title>a &lt; b 'c'</title>\n</g>"
        );
    }

    #[test]
    fn the_root_puts_every_child_on_its_own_line() {
        let doc = Element::document()
            .add(Element::new("metadata").add(Node::Text("{}".into())))
            .add(Node::Raw("<g/>".into()));
        assert_eq!(
            doc.to_document(),
            "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<metadata>{}</metadata>\n<g/>\n</svg>\n"
        );
    }

    #[test]
    fn a_block_takes_lines_of_its_own_in_any_element() {
        let g = Element::new("g")
            .add(Node::Block("<g/>".into()))
            .add(Element::new("animate"));
        let mut out = String::new();
        g.write(&mut out, false);
        assert_eq!(out, "<g>\n<g/>\n<animate/>\n</g>");
    }
}
