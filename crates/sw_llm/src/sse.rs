//! Server-sent events as chat-completion servers send them: `data:` lines (with or
//! without a space), comments, CRLF line ends, events split over several `data:` lines,
//! and a final `data: [DONE]` that some servers leave out.

/// One event's data.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum SseEvent {
    Data(String),
    Done,
}

/// Splits a byte stream into events.
#[derive(Debug, Default)]
pub(crate) struct SseParser {
    line: Vec<u8>,
    data: Vec<String>,
    event: Option<String>,
}

impl SseParser {
    /// Feeds bytes; returns the events they completed.
    pub fn push(&mut self, bytes: &[u8]) -> Vec<SseEvent> {
        let mut out = Vec::new();
        for &b in bytes {
            if b == b'\n' {
                let line = String::from_utf8_lossy(&self.line).trim_end_matches('\r').to_string();
                self.line.clear();
                self.line_done(&line, &mut out);
            } else {
                self.line.push(b);
            }
        }
        out
    }

    /// The end of the stream: a last event not followed by a blank line still counts.
    pub fn finish(&mut self) -> Vec<SseEvent> {
        let mut out = Vec::new();
        if !self.line.is_empty() {
            let line = String::from_utf8_lossy(&self.line).trim_end_matches('\r').to_string();
            self.line.clear();
            self.line_done(&line, &mut out);
        }
        self.dispatch(&mut out);
        out
    }

    fn line_done(&mut self, line: &str, out: &mut Vec<SseEvent>) {
        if line.is_empty() {
            self.dispatch(out);
            return;
        }
        if line.starts_with(':') {
            return;
        }
        let (field, value) = match line.split_once(':') {
            Some((f, v)) => (f, v.strip_prefix(' ').unwrap_or(v)),
            None => (line, ""),
        };
        match field {
            "data" => {
                // Servers that forget the blank line between events: a new complete JSON
                // object after a complete one starts a new event.
                if value.trim() == "[DONE]" {
                    self.dispatch(out);
                    out.push(SseEvent::Done);
                    return;
                }
                if !self.data.is_empty() && value.trim_start().starts_with('{') && self.complete_json() {
                    self.dispatch(out);
                }
                self.data.push(value.to_string());
            }
            "event" => self.event = Some(value.to_string()),
            _ => {}
        }
    }

    fn complete_json(&self) -> bool {
        serde_json::from_str::<serde_json::Value>(&self.data.join("\n")).is_ok()
    }

    fn dispatch(&mut self, out: &mut Vec<SseEvent>) {
        if self.data.is_empty() {
            self.event = None;
            return;
        }
        let data = std::mem::take(&mut self.data).join("\n");
        let is_error = self.event.take().is_some_and(|e| e == "error");
        if is_error && !data.contains("\"error\"") {
            out.push(SseEvent::Data(serde_json::json!({ "error": { "message": data } }).to_string()));
        } else {
            out.push(SseEvent::Data(data));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quirks() {
        let mut p = SseParser::default();
        let mut ev = p.push(b": keep-alive\r\n\r\ndata: {\"a\":1}\r\n\r\ndata:{\"b\":2}\n\ndata: {\"c\":");
        ev.extend(p.push(b"3}\ndata: {\"d\":4}\n\ndata: [DONE]\n\n"));
        assert_eq!(
            ev,
            vec![
                SseEvent::Data("{\"a\":1}".into()),
                SseEvent::Data("{\"b\":2}".into()),
                SseEvent::Data("{\"c\":3}".into()),
                SseEvent::Data("{\"d\":4}".into()),
                SseEvent::Done
            ]
        );
        let mut p = SseParser::default();
        assert!(p.push(b"data: {\"e\":5}").is_empty());
        assert_eq!(p.finish(), vec![SseEvent::Data("{\"e\":5}".into())]);
    }
}
