//! A minimal owned XML tree for MJCF: parse with roxmltree, edit, write deterministically.

use std::fmt::Write as _;

/// One XML element with ordered attributes and children. Comments and processing
/// instructions are not kept; text content is (MJCF rarely uses it).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Element {
    pub name: String,
    pub attrs: Vec<(String, String)>,
    pub children: Vec<Element>,
    /// A comment written just before this element (output only).
    pub comment: Option<String>,
}

/// An XML document that could not be read.
#[derive(Debug, thiserror::Error)]
#[error("line {line}, column {column}: {message}")]
pub struct XmlError {
    pub line: u32,
    pub column: u32,
    pub message: String,
}

impl Element {
    pub fn new(name: &str) -> Self {
        Self { name: name.to_string(), ..Self::default() }
    }

    /// Builder: adds or replaces an attribute.
    pub fn with(mut self, key: &str, value: impl Into<String>) -> Self {
        self.set(key, value);
        self
    }

    /// Builder: appends a child.
    pub fn child(mut self, child: Element) -> Self {
        self.children.push(child);
        self
    }

    pub fn set(&mut self, key: &str, value: impl Into<String>) {
        let value = value.into();
        match self.attrs.iter_mut().find(|(k, _)| k == key) {
            Some((_, v)) => *v = value,
            None => self.attrs.push((key.to_string(), value)),
        }
    }

    pub fn get(&self, key: &str) -> Option<&str> {
        self.attrs.iter().find(|(k, _)| k == key).map(|(_, v)| v.as_str())
    }

    pub fn remove(&mut self, key: &str) -> Option<String> {
        let i = self.attrs.iter().position(|(k, _)| k == key)?;
        Some(self.attrs.remove(i).1)
    }

    pub fn first(&self, name: &str) -> Option<&Element> {
        self.children.iter().find(|c| c.name == name)
    }

    pub fn first_mut(&mut self, name: &str) -> Option<&mut Element> {
        self.children.iter_mut().find(|c| c.name == name)
    }

    /// The first child named `name`, created (appended) if missing.
    pub fn section(&mut self, name: &str) -> &mut Element {
        let i = match self.children.iter().position(|c| c.name == name) {
            Some(i) => i,
            None => {
                self.children.push(Element::new(name));
                self.children.len() - 1
            }
        };
        &mut self.children[i]
    }

    /// Visits this element and all descendants, depth-first, in document order.
    pub fn walk(&self, f: &mut impl FnMut(&Element)) {
        f(self);
        for c in &self.children {
            c.walk(f);
        }
    }

    pub fn walk_mut(&mut self, f: &mut impl FnMut(&mut Element)) {
        f(self);
        for c in &mut self.children {
            c.walk_mut(f);
        }
    }

    /// Parses a document and returns its root element.
    pub fn parse(text: &str) -> Result<Element, XmlError> {
        let doc = roxmltree::Document::parse(text).map_err(|e| {
            let pos = e.pos();
            XmlError { line: pos.row, column: pos.col, message: e.to_string() }
        })?;
        Ok(convert(doc.root_element()))
    }

    /// Writes the element as an indented document with an XML declaration.
    pub fn to_document(&self) -> String {
        let mut out = String::from("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n");
        self.write(&mut out, 0);
        out
    }

    fn write(&self, out: &mut String, depth: usize) {
        let pad = "  ".repeat(depth);
        if let Some(c) = &self.comment {
            let safe = c.replace("--", "- -");
            let _ = writeln!(out, "{pad}<!-- {safe} -->");
        }
        let _ = write!(out, "{pad}<{}", self.name);
        for (k, v) in &self.attrs {
            let _ = write!(out, " {k}=\"{}\"", escape(v));
        }
        if self.children.is_empty() {
            out.push_str("/>\n");
        } else {
            out.push_str(">\n");
            for c in &self.children {
                c.write(out, depth + 1);
            }
            let _ = writeln!(out, "{pad}</{}>", self.name);
        }
    }
}

fn convert(node: roxmltree::Node<'_, '_>) -> Element {
    Element {
        name: node.tag_name().name().to_string(),
        attrs: node.attributes().map(|a| (a.name().to_string(), a.value().to_string())).collect(),
        children: node.children().filter(roxmltree::Node::is_element).map(convert).collect(),
        comment: None,
    }
}

/// Escapes text for an attribute value.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\n' => out.push_str("&#10;"),
            c if c.is_control() => {}
            c => out.push(c),
        }
    }
    out
}

/// Formats a number for MJCF: at most 6 decimals, no trailing zeros, never "-0".
pub fn num(x: f64) -> String {
    if !x.is_finite() {
        return "0".into();
    }
    let mut s = format!("{:.6}", x);
    if s.contains('.') {
        s = s.trim_end_matches('0').trim_end_matches('.').to_string();
    }
    if s == "-0" { "0".into() } else { s }
}

/// Formats a small positive physical quantity (mass, inertia) to 5 significant digits, in
/// scientific notation below 0.001 so that it is never printed as 0.
pub fn sig(x: f64) -> String {
    if !x.is_finite() || x == 0.0 || x.abs() >= 1e-3 {
        return num(x);
    }
    let s = format!("{x:.4e}");
    match s.split_once('e') {
        Some((m, e)) => format!("{}e{e}", m.trim_end_matches('0').trim_end_matches('.')),
        None => s,
    }
}

/// Formats a list of numbers, space separated.
pub fn nums(xs: &[f64]) -> String {
    xs.iter().map(|x| num(*x)).collect::<Vec<_>>().join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_and_stable() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(0.1 + 0.2), "0.3");
        assert_eq!(num(-0.0000001), "0");
        assert_eq!(num(-2.5), "-2.5");
        assert_eq!(num(f64::NAN), "0");
        assert_eq!(nums(&[1.0, 0.25, 3.0]), "1 0.25 3");
        assert_eq!(sig(1.25e-7), "1.25e-7");
        assert_eq!(sig(0.5), "0.5");
    }

    #[test]
    fn parse_edit_write_round_trip() {
        let e =
            Element::parse(r#"<mujoco model="a &amp; b"><!-- c --><worldbody><body name="x"/></worldbody></mujoco>"#)
                .unwrap();
        assert_eq!(e.get("model"), Some("a & b"));
        let text = e.to_document();
        assert!(text.contains(r#"<mujoco model="a &amp; b">"#));
        assert!(text.contains(r#"<body name="x"/>"#));
        let err = Element::parse("<mujoco><worldbody></mujoco>").unwrap_err();
        assert_eq!(err.line, 1);
    }
}
