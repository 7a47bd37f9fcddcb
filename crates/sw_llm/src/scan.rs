//! Incremental reading of a streamed JSON answer: each element of a top-level array
//! field (the plan's `objects`) is handed out as soon as its closing brace arrives, so
//! the work it needs can start while the model is still writing the rest.

/// Finds completed elements of `field` (an array of objects at the top level) in a
/// document that arrives in pieces. Text before the document (prose, a code fence) is
/// skipped. The final document is still parsed as a whole; this only makes early work
/// possible.
#[derive(Debug, Clone)]
pub struct ArrayScanner {
    field: String,
    buf: String,
    /// Bytes of `buf` already scanned.
    pos: usize,
    stack: Vec<Frame>,
    in_string: bool,
    escape: bool,
    /// Start of the string being read (for keys at the top level).
    string_start: usize,
    /// Start of the element being read.
    element_start: Option<usize>,
    /// Elements handed out so far.
    emitted: usize,
    done: bool,
}

#[derive(Debug, Clone)]
struct Frame {
    object: bool,
    expect_key: bool,
    key: Option<String>,
    /// This array is the field's value.
    target: bool,
}

impl ArrayScanner {
    pub fn new(field: &str) -> Self {
        Self {
            field: field.to_string(),
            buf: String::new(),
            pos: 0,
            stack: Vec::new(),
            in_string: false,
            escape: false,
            string_start: 0,
            element_start: None,
            emitted: 0,
            done: false,
        }
    }

    /// Forgets everything (the answer is being streamed again after a retry).
    pub fn reset(&mut self) {
        *self = Self::new(&self.field);
    }

    /// Elements handed out so far.
    pub fn emitted(&self) -> usize {
        self.emitted
    }

    /// Adds a piece of the answer; returns the elements it completed, as JSON text.
    pub fn push(&mut self, piece: &str) -> Vec<String> {
        self.buf.push_str(piece);
        let mut out = Vec::new();
        let bytes = self.buf.as_bytes();
        let mut i = self.pos;
        while i < bytes.len() && !self.done {
            let b = bytes[i];
            if self.in_string {
                if self.escape {
                    self.escape = false;
                } else if b == b'\\' {
                    self.escape = true;
                } else if b == b'"' {
                    self.in_string = false;
                    if self.stack.len() == 1
                        && let Some(top) = self.stack.last_mut()
                        && top.object
                        && top.expect_key
                    {
                        top.key = Some(String::from_utf8_lossy(&bytes[self.string_start + 1..i]).into_owned());
                    }
                }
                i += 1;
                continue;
            }
            match b {
                b'"' if !self.stack.is_empty() => {
                    self.in_string = true;
                    self.string_start = i;
                }
                b'{' | b'[' => {
                    let object = b == b'{';
                    if self.stack.is_empty() && !object {
                        // Text before the document: "[" in prose is not the document.
                        i += 1;
                        continue;
                    }
                    let target = !object
                        && self.stack.len() == 1
                        && self.stack[0].object
                        && self.stack[0].key.as_deref() == Some(self.field.as_str());
                    if object && self.stack.last().is_some_and(|f| f.target) {
                        self.element_start = Some(i);
                    }
                    self.stack.push(Frame { object, expect_key: object, key: None, target });
                }
                b'}' | b']' => {
                    self.stack.pop();
                    if b == b'}'
                        && self.stack.last().is_some_and(|f| f.target)
                        && let Some(start) = self.element_start.take()
                    {
                        out.push(self.buf[start..=i].to_string());
                        self.emitted += 1;
                    }
                    if self.stack.is_empty() {
                        self.done = true;
                    }
                }
                b':' => {
                    if let Some(top) = self.stack.last_mut()
                        && top.object
                    {
                        top.expect_key = false;
                    }
                }
                b',' => {
                    if let Some(top) = self.stack.last_mut()
                        && top.object
                    {
                        top.expect_key = true;
                    }
                }
                _ => {}
            }
            i += 1;
        }
        self.pos = i;
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elements_are_handed_out_as_they_close_whatever_the_chunking() {
        let doc = "Here you go:\n```json\n{\"room\": {\"kind\": \"lab\"}, \"objects\": [{\"id\": \"a\", \"label\": \"x } [\"}, {\"id\": \"b\", \"nested\": {\"objects\": [{}]}}], \"relations\": [{\"subject\": \"a\"}]}\n```";
        for chunk in [1, 2, 3, 7, 1000] {
            let mut s = ArrayScanner::new("objects");
            let mut got = Vec::new();
            let chars: Vec<char> = doc.chars().collect();
            for piece in chars.chunks(chunk) {
                let piece: String = piece.iter().collect();
                got.extend(s.push(&piece));
            }
            assert_eq!(got.len(), 2, "chunk {chunk}: {got:?}");
            assert!(got[0].contains("\"a\"") && got[1].contains("\"b\""));
            for g in &got {
                serde_json::from_str::<serde_json::Value>(g).unwrap();
            }
        }
    }

    #[test]
    fn only_the_top_level_field_counts() {
        let mut s = ArrayScanner::new("objects");
        let got = s.push(r#"{"room": {"objects": [{"x": 1}]}, "robots": [{"id": "r"}]}"#);
        assert!(got.is_empty(), "{got:?}");
        s.reset();
        assert_eq!(s.push(r#"{"objects": [{"x": 1}]}"#).len(), 1);
    }
}
