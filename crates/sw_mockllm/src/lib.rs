//! A local OpenAI-compatible chat-completions server for tests and benchmarks: real
//! HTTP on loopback, answers decided per request by a responder you give it.
//!
//! It can answer whole or streamed (server-sent events, chunked transfer), replay
//! recorded response bodies byte for byte, and inject every fault a real endpoint
//! shows: malformed JSON, prose, schema-invalid documents, 429 with `Retry-After`, 500,
//! streams that break off, silence past the client's timeout, a model that loops until
//! the token limit, streams that end without a finish reason, a server loading its model
//! — and it counts the answers whose client went away before they were written. Every
//! request is logged for assertions; `GET …/models` is routed to the responder too.
//!
//! ```no_run
//! use sw_mockllm::{MockServer, Reply};
//! let server = MockServer::start(|_req| Reply::answer(r#"{"ok": true}"#)).unwrap();
//! println!("point the client at {}", server.base_url());
//! ```

use std::collections::VecDeque;
use std::io::{BufRead, BufReader, Read, Write};
use std::net::{Shutdown, SocketAddr, TcpListener, TcpStream};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use serde_json::{Value, json};

/// A request the server received.
#[derive(Debug, Clone)]
pub struct Request {
    pub method: String,
    /// Path and query, e.g. `/v1/chat/completions`.
    pub path: String,
    /// Header names in lowercase.
    pub headers: Vec<(String, String)>,
    pub body: String,
}

impl Request {
    pub fn json(&self) -> Option<Value> {
        serde_json::from_str(&self.body).ok()
    }

    pub fn header(&self, name: &str) -> Option<&str> {
        let name = name.to_ascii_lowercase();
        self.headers.iter().find(|(k, _)| *k == name).map(|(_, v)| v.as_str())
    }

    pub fn model(&self) -> String {
        self.json().and_then(|v| v.get("model").and_then(Value::as_str).map(str::to_string)).unwrap_or_default()
    }

    pub fn wants_stream(&self) -> bool {
        self.json().and_then(|v| v.get("stream").and_then(Value::as_bool)).unwrap_or(false)
    }

    /// The `response_format.type` asked for, if any (`json_schema`, `json_object`).
    pub fn response_format(&self) -> Option<String> {
        self.json().and_then(|v| v.pointer("/response_format/type").and_then(Value::as_str).map(str::to_string))
    }

    /// Every message's content, in order.
    pub fn messages(&self) -> Vec<(String, String)> {
        self.json()
            .and_then(|v| v.get("messages").and_then(Value::as_array).cloned())
            .unwrap_or_default()
            .iter()
            .map(|m| {
                let role = m.get("role").and_then(Value::as_str).unwrap_or("").to_string();
                let content = m.get("content").and_then(Value::as_str).unwrap_or("").to_string();
                (role, content)
            })
            .collect()
    }

    /// The last user message.
    pub fn last_user(&self) -> String {
        self.messages().into_iter().rev().find(|(r, _)| r == "user").map(|(_, c)| c).unwrap_or_default()
    }
}

/// What to answer.
#[derive(Debug, Clone, PartialEq)]
pub enum Reply {
    /// A chat completion with this content: streamed in a few chunks when the request
    /// asked for a stream, else one JSON document, after `delay`.
    Answer { content: String, delay: Duration },
    /// Streamed in `chunks` pieces: the first after `first`, the rest spread evenly until
    /// `total`. Without `done` the stream ends with no `[DONE]` (but a finish reason).
    Stream { content: String, chunks: usize, first: Duration, total: Duration, done: bool },
    /// Streams the first `fraction` of `content`, then drops the connection.
    Truncated { content: String, fraction: f64 },
    /// An error status with this body (`Retry-After` when set).
    Status { code: u16, body: String, retry_after: Option<u32> },
    /// Exactly these bytes as the body (a recorded response), after `delay`.
    Raw { status: u16, content_type: String, body: Vec<u8>, delay: Duration },
    /// Reads the request, then says nothing for this long and closes the connection.
    Hang(Duration),
    /// A stream of `pieces` pieces of `content`, one every `gap` (the first at once), as
    /// a local server writes tokens; then the finish reason (`None`: none, as
    /// llama-cpp-python's interrupted streams), `[DONE]` when `done`. Chunks name
    /// `model` when set (a server answering with its own model's name), else the one
    /// asked for.
    Tokens { content: String, pieces: usize, gap: Duration, finish: Option<String>, done: bool, model: Option<String> },
}

impl Reply {
    pub fn answer(content: impl Into<String>) -> Reply {
        Reply::Answer { content: content.into(), delay: Duration::ZERO }
    }

    pub fn answer_after(content: impl Into<String>, delay: Duration) -> Reply {
        Reply::Answer { content: content.into(), delay }
    }

    /// A stream of `chunks` pieces over `total`, the first after a tenth of it.
    pub fn stream(content: impl Into<String>, chunks: usize, total: Duration) -> Reply {
        Reply::Stream { content: content.into(), chunks: chunks.max(1), first: total / 10, total, done: true }
    }

    /// A stream of `pieces` pieces, one every `gap`, ending normally (`stop`, `[DONE]`).
    pub fn tokens(content: impl Into<String>, pieces: usize, gap: Duration) -> Reply {
        Reply::Tokens {
            content: content.into(),
            pieces: pieces.max(1),
            gap,
            finish: Some("stop".into()),
            done: true,
            model: None,
        }
    }

    /// What llama.cpp's server answers while it loads its model.
    pub fn loading() -> Reply {
        Reply::Status {
            code: 503,
            body: json!({ "error": { "code": 503, "message": "Loading model", "type": "unavailable_error" } })
                .to_string(),
            retry_after: None,
        }
    }

    /// `GET /v1/models` of a server holding these models.
    pub fn models(ids: &[&str]) -> Reply {
        let data: Vec<Value> =
            ids.iter().map(|id| json!({ "id": id, "object": "model", "owned_by": "mock" })).collect();
        Reply::recorded(json!({ "object": "list", "data": data }).to_string(), "application/json")
    }

    pub fn status(code: u16, message: &str) -> Reply {
        Reply::Status {
            code,
            body: json!({ "error": { "message": message, "type": "mock" } }).to_string(),
            retry_after: None,
        }
    }

    pub fn rate_limited(retry_after_s: u32) -> Reply {
        Reply::Status {
            code: 429,
            body: json!({ "error": { "message": "Rate limit reached", "type": "rate_limit" } }).to_string(),
            retry_after: Some(retry_after_s),
        }
    }

    /// A recorded response body, replayed byte for byte with status 200.
    pub fn recorded(body: impl Into<Vec<u8>>, content_type: &str) -> Reply {
        Reply::Raw { status: 200, content_type: content_type.to_string(), body: body.into(), delay: Duration::ZERO }
    }

    /// An `/embeddings` answer for the request's `input`: per text, a unit vector of
    /// `dims` hashed character trigrams (texts sharing words point the same way), in
    /// the provider's shape with usage. A request without inputs gets a 400.
    pub fn embeddings(req: &Request, dims: usize) -> Reply {
        let inputs: Vec<String> = match req.json().and_then(|v| v.get("input").cloned()) {
            Some(Value::String(s)) => vec![s],
            Some(Value::Array(a)) => a.iter().filter_map(|x| x.as_str().map(str::to_string)).collect(),
            _ => return Reply::status(400, "'input' is required"),
        };
        let dims = dims.max(1);
        let data: Vec<Value> = inputs
            .iter()
            .enumerate()
            .map(|(i, t)| json!({ "object": "embedding", "index": i, "embedding": trigram_vector(t, dims) }))
            .collect();
        let tokens: usize = inputs.iter().map(|t| t.len().div_ceil(4)).sum();
        let body = json!({ "object": "list", "data": data, "model": req.model(), "usage": { "prompt_tokens": tokens, "total_tokens": tokens } });
        Reply::recorded(body.to_string(), "application/json")
    }
}

/// A unit vector of hashed character trigrams of the lower-cased, padded words.
fn trigram_vector(text: &str, dims: usize) -> Vec<f32> {
    let mut v = vec![0f32; dims];
    for word in text.to_lowercase().split(|c: char| !c.is_alphanumeric()).filter(|w| !w.is_empty()) {
        let padded: Vec<char> = format!(" {word} ").chars().collect();
        for w in padded.windows(3) {
            let mut h: u64 = 0xcbf2_9ce4_8422_2325;
            for c in w {
                h = (h ^ u64::from(*c)).wrapping_mul(0x0100_0000_01b3);
            }
            v[(h % dims as u64) as usize] += 1.0;
        }
    }
    let n = v.iter().map(|x| x * x).sum::<f32>().sqrt();
    if n > 0.0 {
        v.iter_mut().for_each(|x| *x /= n);
    }
    v
}

type Responder = dyn Fn(&Request) -> Reply + Send + Sync;

/// Replies in order; the last one repeats.
pub fn script(replies: Vec<Reply>) -> impl Fn(&Request) -> Reply + Send + Sync + 'static {
    let queue = Mutex::new(VecDeque::from(replies));
    move |_req| {
        let mut q = match queue.lock() {
            Ok(q) => q,
            Err(p) => p.into_inner(),
        };
        if q.len() > 1 {
            q.pop_front().unwrap_or_else(|| Reply::status(500, "script empty"))
        } else {
            q.front().cloned().unwrap_or_else(|| Reply::status(500, "script empty"))
        }
    }
}

/// The server. It stops when dropped.
pub struct MockServer {
    addr: SocketAddr,
    stop: Arc<AtomicBool>,
    log: Arc<Mutex<Vec<Request>>>,
    gone: Arc<AtomicU64>,
    accept: Option<JoinHandle<()>>,
}

impl std::fmt::Debug for MockServer {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("MockServer").field("addr", &self.addr).finish()
    }
}

impl MockServer {
    /// Listens on an ephemeral loopback port and answers each request with `responder`.
    pub fn start(responder: impl Fn(&Request) -> Reply + Send + Sync + 'static) -> std::io::Result<MockServer> {
        Self::start_at("127.0.0.1:0", responder)
    }

    /// Listens on `addr` (a server started again on the port of one that stopped: a
    /// restart).
    pub fn start_at(
        addr: &str,
        responder: impl Fn(&Request) -> Reply + Send + Sync + 'static,
    ) -> std::io::Result<MockServer> {
        let listener = TcpListener::bind(addr)?;
        let addr = listener.local_addr()?;
        let stop = Arc::new(AtomicBool::new(false));
        let log: Arc<Mutex<Vec<Request>>> = Arc::new(Mutex::new(Vec::new()));
        let gone = Arc::new(AtomicU64::new(0));
        let responder: Arc<Responder> = Arc::new(responder);
        let (s, l, g) = (Arc::clone(&stop), Arc::clone(&log), Arc::clone(&gone));
        let accept = std::thread::Builder::new().name("mockllm-accept".into()).spawn(move || {
            for conn in listener.incoming() {
                if s.load(Ordering::SeqCst) {
                    break;
                }
                let Ok(conn) = conn else { continue };
                let (s, l, r, g) = (Arc::clone(&s), Arc::clone(&l), Arc::clone(&responder), Arc::clone(&g));
                let _ = std::thread::Builder::new().name("mockllm-conn".into()).spawn(move || {
                    if serve(conn, &*r, &l, &s).is_err() {
                        g.fetch_add(1, Ordering::SeqCst);
                    }
                });
            }
        })?;
        Ok(MockServer { addr, stop, log, gone, accept: Some(accept) })
    }

    pub fn addr(&self) -> SocketAddr {
        self.addr
    }

    /// `http://127.0.0.1:<port>/v1`: the base URL to configure.
    pub fn base_url(&self) -> String {
        format!("http://{}/v1", self.addr)
    }

    /// Answers the server could not finish writing because the client had gone (closed
    /// its connection): a cancelled or abandoned call.
    pub fn abandoned(&self) -> u64 {
        self.gone.load(Ordering::SeqCst)
    }

    /// Every request so far.
    pub fn requests(&self) -> Vec<Request> {
        match self.log.lock() {
            Ok(l) => l.clone(),
            Err(p) => p.into_inner().clone(),
        }
    }
}

impl Drop for MockServer {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::SeqCst);
        // Wake the accept loop.
        let _ = TcpStream::connect_timeout(&self.addr, Duration::from_millis(200));
        if let Some(h) = self.accept.take() {
            let _ = h.join();
        }
    }
}

/// Sleeps in small steps so that a stopping server does not wait for long sleeps.
fn pause(d: Duration, stop: &AtomicBool) -> bool {
    let end = Instant::now() + d;
    while Instant::now() < end {
        if stop.load(Ordering::SeqCst) {
            return false;
        }
        std::thread::sleep((end - Instant::now()).min(Duration::from_millis(5)));
    }
    true
}

fn read_request(conn: &TcpStream) -> std::io::Result<Request> {
    conn.set_read_timeout(Some(Duration::from_secs(10)))?;
    let mut reader = BufReader::new(conn.try_clone()?);
    let mut line = String::new();
    reader.read_line(&mut line)?;
    let mut parts = line.split_whitespace();
    let method = parts.next().unwrap_or("").to_string();
    let path = parts.next().unwrap_or("").to_string();
    let mut headers = Vec::new();
    loop {
        let mut h = String::new();
        if reader.read_line(&mut h)? == 0 {
            break;
        }
        let h = h.trim_end();
        if h.is_empty() {
            break;
        }
        if let Some((k, v)) = h.split_once(':') {
            headers.push((k.trim().to_ascii_lowercase(), v.trim().to_string()));
        }
    }
    let len = headers.iter().find(|(k, _)| k == "content-length").and_then(|(_, v)| v.parse::<usize>().ok());
    let chunked = headers.iter().any(|(k, v)| k == "transfer-encoding" && v.to_ascii_lowercase().contains("chunked"));
    let mut body = Vec::new();
    if let Some(n) = len {
        body.resize(n.min(64 << 20), 0);
        reader.read_exact(&mut body)?;
    } else if chunked {
        loop {
            let mut size = String::new();
            reader.read_line(&mut size)?;
            let n = usize::from_str_radix(size.trim().split(';').next().unwrap_or("0"), 16).unwrap_or(0);
            if n == 0 {
                let mut end = String::new();
                let _ = reader.read_line(&mut end);
                break;
            }
            let mut chunk = vec![0u8; n + 2];
            reader.read_exact(&mut chunk)?;
            body.extend_from_slice(&chunk[..n]);
        }
    }
    Ok(Request { method, path, headers, body: String::from_utf8_lossy(&body).into_owned() })
}

static IDS: AtomicU64 = AtomicU64::new(0);

fn completion(content: &str, model: &str, prompt_tokens: usize) -> Value {
    json!({
        "id": format!("chatcmpl-mock-{}", IDS.fetch_add(1, Ordering::Relaxed)),
        "object": "chat.completion",
        "created": 0,
        "model": model,
        "choices": [{ "index": 0, "message": { "role": "assistant", "content": content }, "finish_reason": "stop" }],
        "usage": { "prompt_tokens": prompt_tokens, "completion_tokens": content.len().div_ceil(4), "total_tokens": prompt_tokens + content.len().div_ceil(4) }
    })
}

fn chunk(piece: Option<&str>, finish: Option<&str>, model: &str) -> String {
    let delta = match piece {
        Some(p) => json!({ "content": p }),
        None => json!({}),
    };
    let v = json!({
        "id": "chatcmpl-mock-stream", "object": "chat.completion.chunk", "created": 0, "model": model,
        "choices": [{ "index": 0, "delta": delta, "finish_reason": finish }]
    });
    format!("data: {v}\n\n")
}

/// Splits at character boundaries into `n` nearly equal pieces.
fn pieces(content: &str, n: usize) -> Vec<String> {
    let chars: Vec<char> = content.chars().collect();
    let n = n.clamp(1, chars.len().max(1));
    let size = chars.len().div_ceil(n).max(1);
    chars.chunks(size).map(|c| c.iter().collect()).collect()
}

struct Writer<'a> {
    conn: &'a TcpStream,
}

impl Writer<'_> {
    fn head(&mut self, status: u16, content_type: &str, extra: &str, len: Option<usize>) -> std::io::Result<()> {
        let reason = match status {
            200 => "OK",
            400 => "Bad Request",
            401 => "Unauthorized",
            404 => "Not Found",
            422 => "Unprocessable Entity",
            429 => "Too Many Requests",
            500 => "Internal Server Error",
            502 => "Bad Gateway",
            503 => "Service Unavailable",
            _ => "Status",
        };
        let length = match len {
            Some(n) => format!("content-length: {n}\r\n"),
            None => "transfer-encoding: chunked\r\n".to_string(),
        };
        write!(
            self.conn,
            "HTTP/1.1 {status} {reason}\r\ncontent-type: {content_type}\r\n{length}{extra}connection: close\r\n\r\n"
        )?;
        self.conn.flush()
    }

    fn chunk(&mut self, data: &str) -> std::io::Result<()> {
        write!(self.conn, "{:x}\r\n{data}\r\n", data.len())?;
        self.conn.flush()
    }

    fn end(&mut self) -> std::io::Result<()> {
        write!(self.conn, "0\r\n\r\n")?;
        self.conn.flush()
    }
}

fn serve(conn: TcpStream, responder: &Responder, log: &Mutex<Vec<Request>>, stop: &AtomicBool) -> std::io::Result<()> {
    // Streamed pieces go out as they are written, as a real server's do.
    conn.set_nodelay(true)?;
    // A connection that sends no request is not an answer the client abandoned.
    let Ok(req) = read_request(&conn) else { return Ok(()) };
    if let Ok(mut l) = log.lock() {
        l.push(req.clone());
    }
    let model = req.model();
    let prompt_tokens = req.body.len().div_ceil(4);
    let routed = (req.method == "POST"
        && (req.path.ends_with("/chat/completions") || req.path.ends_with("/embeddings")))
        || (req.method == "GET" && req.path.ends_with("/models"));
    let reply =
        if routed { responder(&req) } else { Reply::status(404, &format!("no route {} {}", req.method, req.path)) };
    let mut w = Writer { conn: &conn };
    match reply {
        Reply::Answer { content, delay } => {
            if !pause(delay, stop) {
                return Ok(());
            }
            if req.wants_stream() {
                w.head(200, "text/event-stream", "", None)?;
                for p in pieces(&content, 4) {
                    w.chunk(&chunk(Some(&p), None, &model))?;
                }
                w.chunk(&chunk(None, Some("stop"), &model))?;
                let usage = json!({ "choices": [], "usage": { "prompt_tokens": prompt_tokens, "completion_tokens": content.len().div_ceil(4) } });
                w.chunk(&format!("data: {usage}\n\n"))?;
                w.chunk("data: [DONE]\n\n")?;
                w.end()?;
            } else {
                let body = completion(&content, &model, prompt_tokens).to_string();
                w.head(200, "application/json", "", Some(body.len()))?;
                w.conn.write_all(body.as_bytes())?;
            }
        }
        Reply::Stream { content, chunks, first, total, done } => {
            w.head(200, "text/event-stream", "", None)?;
            let ps = pieces(&content, chunks);
            if !pause(first, stop) {
                return Ok(());
            }
            // Each piece is due at a fixed time from the first, so sleep overshoots do not
            // add up over many pieces.
            let start = Instant::now();
            let gap = if ps.len() > 1 { total.saturating_sub(first) / (ps.len() as u32) } else { Duration::ZERO };
            for (i, p) in ps.iter().enumerate() {
                let due = start + gap * (i as u32);
                if i > 0 && !pause(due.saturating_duration_since(Instant::now()), stop) {
                    return Ok(());
                }
                w.chunk(&chunk(Some(p), None, &model))?;
            }
            w.chunk(&chunk(None, Some("stop"), &model))?;
            if done {
                w.chunk("data: [DONE]\n\n")?;
            }
            w.end()?;
        }
        Reply::Truncated { content, fraction } => {
            w.head(200, "text/event-stream", "", None)?;
            let keep = ((content.chars().count() as f64) * fraction.clamp(0.0, 1.0)) as usize;
            let part: String = content.chars().take(keep).collect();
            for p in pieces(&part, 3) {
                w.chunk(&chunk(Some(&p), None, &model))?;
            }
            // Half a chunk, then the connection goes away.
            w.conn.write_all(b"40\r\ndata: {\"choi")?;
            w.conn.flush()?;
            let _ = conn.shutdown(Shutdown::Both);
        }
        Reply::Status { code, body, retry_after } => {
            let extra = retry_after.map(|s| format!("retry-after: {s}\r\n")).unwrap_or_default();
            w.head(code, "application/json", &extra, Some(body.len()))?;
            w.conn.write_all(body.as_bytes())?;
        }
        Reply::Raw { status, content_type, body, delay } => {
            if !pause(delay, stop) {
                return Ok(());
            }
            w.head(status, &content_type, "", Some(body.len()))?;
            w.conn.write_all(&body)?;
        }
        Reply::Hang(d) => {
            pause(d, stop);
        }
        Reply::Tokens { content, pieces: n, gap, finish, done, model: served } => {
            let name = served.unwrap_or(model);
            w.head(200, "text/event-stream", "", None)?;
            let start = Instant::now();
            for (i, p) in pieces(&content, n).iter().enumerate() {
                let due = start + gap * (i as u32);
                if i > 0 && !pause(due.saturating_duration_since(Instant::now()), stop) {
                    return Ok(());
                }
                w.chunk(&chunk(Some(p), None, &name))?;
            }
            if let Some(f) = finish {
                w.chunk(&chunk(None, Some(&f), &name))?;
            }
            if done {
                w.chunk("data: [DONE]\n\n")?;
            }
            w.end()?;
        }
    }
    let _ = conn.shutdown(Shutdown::Write);
    Ok(())
}
