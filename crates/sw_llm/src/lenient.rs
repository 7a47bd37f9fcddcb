//! Reading JSON out of what "OpenAI-compatible" models actually answer: code fences,
//! a sentence before or after the document, `<think>` sections, a JSON string holding
//! the JSON, trailing commas, a byte-order mark. Anything else is an error that says
//! what was found (with a short preview, never the whole answer).

use serde_json::Value;

/// Why no JSON document could be read from an answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExtractError {
    #[error("the answer is empty")]
    Empty,
    #[error("the answer holds no JSON object (it begins \"{preview}\")")]
    NoJson { preview: String },
    #[error("the answer's JSON is broken: {message} (it begins \"{preview}\")")]
    Invalid { message: String, preview: String },
}

/// The first characters of `text`, on one line.
pub fn preview(text: &str) -> String {
    let one_line: String = text.chars().map(|c| if c.is_control() { ' ' } else { c }).take(80).collect();
    if text.chars().count() > 80 { format!("{}…", one_line.trim_end()) } else { one_line.trim_end().to_string() }
}

/// Extracts the JSON object of an answer (an array is accepted too).
pub fn extract_json(text: &str) -> Result<Value, ExtractError> {
    extract(text, 0)
}

fn extract(text: &str, depth: u32) -> Result<Value, ExtractError> {
    let text = strip_think(text.trim_start_matches('\u{feff}')).trim().to_string();
    if text.is_empty() {
        return Err(ExtractError::Empty);
    }
    if let Ok(v) = serde_json::from_str::<Value>(&text) {
        match v {
            Value::Object(_) | Value::Array(_) => return Ok(v),
            // A JSON string holding the document (double-encoded).
            Value::String(inner) if depth == 0 => return extract(&inner, 1),
            _ => {}
        }
    }
    let mut first_error: Option<String> = None;
    // Fenced blocks first: ```json … ``` (the language tag is optional).
    for block in fenced_blocks(&text) {
        match parse_candidate(block) {
            Ok(v) => return Ok(v),
            Err(e) => {
                first_error.get_or_insert(e);
            }
        }
    }
    // Then every balanced {…} or […] in order, the first that parses wins.
    let bytes = text.as_bytes();
    let mut start = 0;
    while let Some(off) = text[start..].find(['{', '[']) {
        let at = start + off;
        match balanced_end(bytes, at) {
            Some(end) => match parse_candidate(&text[at..=end]) {
                Ok(v @ Value::Object(_)) => return Ok(v),
                Ok(v @ Value::Array(_)) if bytes[at] == b'[' && looks_like_document(&v) => return Ok(v),
                Ok(_) => {}
                Err(e) => {
                    first_error.get_or_insert(e);
                }
            },
            None => {
                // Unbalanced to the end: the answer was cut off.
                first_error.get_or_insert_with(|| "the document is not closed (cut off?)".into());
            }
        }
        start = at + 1;
    }
    match first_error {
        Some(message) => Err(ExtractError::Invalid { message, preview: preview(&text) }),
        None => Err(ExtractError::NoJson { preview: preview(&text) }),
    }
}

/// An array is taken only when it holds objects (not `[1]` in a sentence).
fn looks_like_document(v: &Value) -> bool {
    v.as_array().is_some_and(|a| !a.is_empty() && a.iter().all(Value::is_object))
}

fn parse_candidate(s: &str) -> Result<Value, String> {
    match serde_json::from_str::<Value>(s) {
        Ok(v) => Ok(v),
        Err(e) => {
            let fixed = remove_trailing_commas(s);
            serde_json::from_str::<Value>(&fixed).map_err(|_| e.to_string())
        }
    }
}

/// Removes `<think>…</think>` sections (reasoning models put them in the content).
fn strip_think(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(i) = rest.find("<think>") {
        out.push_str(&rest[..i]);
        match rest[i..].find("</think>") {
            Some(j) => rest = &rest[i + j + "</think>".len()..],
            None => {
                rest = "";
                break;
            }
        }
    }
    out.push_str(rest);
    out
}

/// Contents of ``` fenced blocks.
fn fenced_blocks(text: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find("```") {
        let after = &rest[i + 3..];
        // Skip the language tag up to the end of the line.
        let body_start = after.find('\n').map_or(after.len(), |n| n + 1);
        let tag = &after[..body_start.min(after.len())];
        let body = if tag.trim().chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-') {
            &after[body_start.min(after.len())..]
        } else {
            after
        };
        match body.find("```") {
            Some(j) => {
                out.push(body[..j].trim());
                rest = &body[j + 3..];
            }
            None => {
                out.push(body.trim());
                break;
            }
        }
    }
    out
}

/// The index of the bracket closing the one at `start`, aware of strings.
pub(crate) fn balanced_end(bytes: &[u8], start: usize) -> Option<usize> {
    let mut depth = 0usize;
    let mut in_string = false;
    let mut escape = false;
    for (i, &b) in bytes.iter().enumerate().skip(start) {
        if in_string {
            if escape {
                escape = false;
            } else if b == b'\\' {
                escape = true;
            } else if b == b'"' {
                in_string = false;
            }
            continue;
        }
        match b {
            b'"' => in_string = true,
            b'{' | b'[' => depth += 1,
            b'}' | b']' => {
                depth = depth.checked_sub(1)?;
                if depth == 0 {
                    return Some(i);
                }
            }
            _ => {}
        }
    }
    None
}

/// `[1, 2,]` → `[1, 2]`, outside strings.
fn remove_trailing_commas(s: &str) -> String {
    let chars: Vec<char> = s.chars().collect();
    let mut out = String::with_capacity(s.len());
    let mut in_string = false;
    let mut escape = false;
    for (i, &c) in chars.iter().enumerate() {
        if in_string {
            out.push(c);
            if escape {
                escape = false;
            } else if c == '\\' {
                escape = true;
            } else if c == '"' {
                in_string = false;
            }
            continue;
        }
        if c == '"' {
            in_string = true;
        }
        if c == ',' {
            let next = chars[i + 1..].iter().find(|c| !c.is_whitespace());
            if matches!(next, Some('}') | Some(']')) {
                continue;
            }
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plain_fenced_prose_and_think() {
        let want = serde_json::json!({"a": 1});
        for text in [
            r#"{"a": 1}"#,
            "```json\n{\"a\": 1}\n```",
            "```\n{\"a\": 1}\n```\nHope this helps!",
            "Here is the plan:\n{\"a\": 1}\nLet me know if you need changes {like this}.",
            "<think>the user wants {a}</think>{\"a\": 1}",
            "\u{feff}{\"a\": 1,}",
            r#""{\"a\": 1}""#,
        ] {
            assert_eq!(extract_json(text).unwrap(), want, "{text}");
        }
    }

    #[test]
    fn prose_and_broken_json_are_errors() {
        assert!(matches!(extract_json("I cannot help with that."), Err(ExtractError::NoJson { .. })));
        assert!(matches!(extract_json("   "), Err(ExtractError::Empty)));
        let e = extract_json(r#"{"a": 1, "b": [1, 2"#).unwrap_err();
        assert!(matches!(e, ExtractError::Invalid { .. }), "{e:?}");
        let e = extract_json(r#"{"a": tru}"#).unwrap_err();
        assert!(e.to_string().contains("broken"), "{e}");
    }

    #[test]
    fn strings_with_brackets_do_not_confuse_the_matcher() {
        let v = extract_json(r#"Sure: {"label": "a } weird { label", "n": [1]} trailing"#).unwrap();
        assert_eq!(v["label"], "a } weird { label");
    }

    #[test]
    fn previews_are_short_and_one_line() {
        let p = preview(&"line\n".repeat(100));
        assert!(p.chars().count() <= 81 && !p.contains('\n'));
    }
}
