//! Which endpoint, key and model each stage uses: from a JSON file, the environment, or
//! code. Nothing is configured by default — the offline pipeline needs no endpoint.
//!
//! ```text
//! SCENEWRIGHT_LLM_BASE_URL=https://api.example.com/v1     every stage
//! SCENEWRIGHT_LLM_MODEL=some-model
//! SCENEWRIGHT_LLM_API_KEY=...                              (else OPENAI_API_KEY)
//! SCENEWRIGHT_LLM_CAD_MODEL=another-model                  one stage: PLAN, RELATIONS,
//!                                                          CAD, EDIT, REFINE, EMBEDDINGS
//! SCENEWRIGHT_LLM_TIMEOUT_S=60  _RETRIES=2  _STREAM=1  _STRUCTURED=1  _CONCURRENCY=8
//! SCENEWRIGHT_LLM_MAX_TOKENS=…  _MAX_CALL_S=300  _LOAD_WAIT_S=60  _ENDPOINT_CONCURRENCY=…
//! SCENEWRIGHT_LLM_CONFIG=llm.json                          a file with the same settings
//! ```
//!
//! The file is JSON: top-level defaults and a `stages` object with per-stage overrides:
//! `{"base_url": "...", "model": "...", "api_key_env": "MY_KEY", "stages": {"cad": {"model": "..."}}}`.
//! Environment variables override the file; per-stage settings override the defaults.

use std::collections::BTreeMap;
use std::fmt;
use std::time::Duration;

use serde::Deserialize;
use sw_plan::LlmStage;

/// An API key. Never printed, logged or recorded.
#[derive(Clone, PartialEq, Eq)]
pub struct ApiKey(String);

impl ApiKey {
    pub fn new(key: impl Into<String>) -> Self {
        Self(key.into())
    }

    pub(crate) fn expose(&self) -> &str {
        &self.0
    }
}

impl fmt::Debug for ApiKey {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("ApiKey(***)")
    }
}

/// One stage's endpoint and how to call it.
#[derive(Debug, Clone, PartialEq)]
pub struct Endpoint {
    /// The API root, e.g. `https://api.openai.com/v1`; `/chat/completions` is appended.
    pub base_url: String,
    pub api_key: Option<ApiKey>,
    pub model: String,
    /// Longest silence of the server in one attempt: until the first byte of the answer,
    /// and between two pieces of a streamed one (a stream that keeps coming is not cut;
    /// `max_tokens` bounds its length). An answer that is not streamed must be complete
    /// within it.
    pub timeout: Duration,
    /// Longest attempt, however it progresses (a safety net behind `max_tokens`).
    pub max_call: Duration,
    /// How long a server that is starting (connection refused, `503 Loading model`) is
    /// waited for before the call fails, on top of the retries.
    pub load_wait: Duration,
    pub connect_timeout: Duration,
    /// Attempts after the first, on 429, 5xx, broken connections and broken-off streams.
    /// A timeout at temperature 0 and an answer cut off at `max_tokens` are deterministic:
    /// they are not asked again unchanged.
    pub max_retries: u32,
    /// First back-off; it doubles per retry (with jitter), up to `max_backoff`. A
    /// server's `Retry-After` is honoured up to `max_backoff`.
    pub backoff: Duration,
    pub max_backoff: Duration,
    /// Send `response_format` with our JSON Schema (structured output).
    pub structured: bool,
    /// Stream answers (every call, whole answers too: the silence timeout, cancellation
    /// and early work need the pieces).
    pub stream: bool,
    /// Send `stream_options.include_usage` with streams (refusals are learnt anyway).
    pub stream_options: bool,
    pub temperature: Option<f64>,
    /// The token limit of every answer; else the caller's, else the stage's default
    /// ([`default_max_tokens`]).
    pub max_tokens: Option<u32>,
    /// Concurrent calls of this stage (the CAD stage runs one per missing asset).
    pub concurrency: usize,
    /// Calls in flight at this endpoint's server at once, whatever the stage; by default
    /// 1 for a server on this machine (one model on a few cores) and no limit elsewhere.
    pub endpoint_concurrency: Option<usize>,
}

/// The token limit of a stage's answers when neither the endpoint nor the caller sets
/// one: the longest plausible answer with room to spare, so that a model that loops is
/// cut off in bounded time.
pub fn default_max_tokens(stage: LlmStage) -> Option<u32> {
    match stage {
        LlmStage::Plan => Some(640),
        LlmStage::Relations => Some(384),
        LlmStage::Cad => Some(1024),
        LlmStage::Edit => Some(256),
        LlmStage::Refine => Some(512),
        LlmStage::Embeddings => None,
    }
}

impl Endpoint {
    /// An endpoint with the default timeouts and retries.
    pub fn new(base_url: impl Into<String>, model: impl Into<String>) -> Self {
        Self {
            base_url: base_url.into(),
            api_key: None,
            model: model.into(),
            timeout: Duration::from_secs(60),
            max_call: Duration::from_secs(300),
            load_wait: Duration::from_secs(60),
            connect_timeout: Duration::from_secs(10),
            max_retries: 2,
            backoff: Duration::from_millis(500),
            max_backoff: Duration::from_secs(8),
            structured: true,
            stream: true,
            stream_options: true,
            temperature: Some(0.0),
            max_tokens: None,
            concurrency: 8,
            endpoint_concurrency: None,
        }
    }

    /// `scheme://host:port` of the endpoint, for telemetry (no path, no credentials).
    pub fn origin(&self) -> String {
        let url = self.base_url.as_str();
        let (scheme, rest) = url.split_once("://").unwrap_or(("http", url));
        let host = rest.split('/').next().unwrap_or("");
        let host = host.rsplit('@').next().unwrap_or(host);
        format!("{scheme}://{host}")
    }

    /// `{base}/chat/completions`.
    pub fn completions_url(&self) -> String {
        let base = self.base_url.trim_end_matches('/');
        if base.ends_with("/chat/completions") { base.to_string() } else { format!("{base}/chat/completions") }
    }

    /// `{base}/embeddings` (a base URL that already names the route is kept).
    pub(crate) fn embeddings_url(&self) -> String {
        let base = self.base_url.trim_end_matches('/');
        if base.ends_with("/embeddings") { base.to_string() } else { format!("{base}/embeddings") }
    }
}

/// Endpoints per stage. A stage with no endpoint does not call a model.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LlmConfig {
    endpoints: BTreeMap<LlmStage, Endpoint>,
}

/// A configuration that cannot be used.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum ConfigError {
    #[error("{source_name}: {message}")]
    Invalid { source_name: String, message: String },
    #[error("cannot read the LLM configuration '{path}': {reason}")]
    Unreadable { path: String, reason: String },
}

/// Settings as written in the file or the environment (every field optional).
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct Settings {
    base_url: Option<String>,
    model: Option<String>,
    api_key: Option<String>,
    api_key_env: Option<String>,
    timeout_s: Option<f64>,
    max_call_s: Option<f64>,
    load_wait_s: Option<f64>,
    connect_timeout_s: Option<f64>,
    retries: Option<u32>,
    backoff_ms: Option<u64>,
    max_backoff_ms: Option<u64>,
    structured: Option<bool>,
    stream: Option<bool>,
    temperature: Option<f64>,
    max_tokens: Option<u32>,
    concurrency: Option<usize>,
    endpoint_concurrency: Option<usize>,
}

#[derive(Debug, Clone, Default)]
struct FileSettings {
    defaults: Settings,
    stages: BTreeMap<String, Settings>,
}

impl Settings {
    /// `other` wins where it is set.
    fn overlay(&self, other: &Settings) -> Settings {
        Settings {
            base_url: other.base_url.clone().or_else(|| self.base_url.clone()),
            model: other.model.clone().or_else(|| self.model.clone()),
            api_key: other
                .api_key
                .clone()
                .or_else(|| if other.api_key_env.is_some() { None } else { self.api_key.clone() }),
            api_key_env: other.api_key_env.clone().or_else(|| self.api_key_env.clone()),
            timeout_s: other.timeout_s.or(self.timeout_s),
            max_call_s: other.max_call_s.or(self.max_call_s),
            load_wait_s: other.load_wait_s.or(self.load_wait_s),
            connect_timeout_s: other.connect_timeout_s.or(self.connect_timeout_s),
            retries: other.retries.or(self.retries),
            backoff_ms: other.backoff_ms.or(self.backoff_ms),
            max_backoff_ms: other.max_backoff_ms.or(self.max_backoff_ms),
            structured: other.structured.or(self.structured),
            stream: other.stream.or(self.stream),
            temperature: other.temperature.or(self.temperature),
            max_tokens: other.max_tokens.or(self.max_tokens),
            concurrency: other.concurrency.or(self.concurrency),
            endpoint_concurrency: other.endpoint_concurrency.or(self.endpoint_concurrency),
        }
    }

    fn from_env(prefix: &str, get: &dyn Fn(&str) -> Option<String>, source: &str) -> Result<Settings, ConfigError> {
        let var = |name: &str| get(&format!("{prefix}{name}")).map(|v| v.trim().to_string()).filter(|v| !v.is_empty());
        let bad = |name: &str, v: &str, what: &str| ConfigError::Invalid {
            source_name: format!("{source} {prefix}{name}"),
            message: format!("'{v}' is not {what}"),
        };
        let num = |name: &str| -> Result<Option<f64>, ConfigError> {
            var(name).map(|v| v.parse::<f64>().map_err(|_| bad(name, &v, "a number"))).transpose()
        };
        let int = |name: &str| -> Result<Option<u64>, ConfigError> {
            var(name).map(|v| v.parse::<u64>().map_err(|_| bad(name, &v, "a whole number"))).transpose()
        };
        let flag = |name: &str| -> Result<Option<bool>, ConfigError> {
            var(name)
                .map(|v| match v.to_ascii_lowercase().as_str() {
                    "1" | "true" | "yes" | "on" => Ok(true),
                    "0" | "false" | "no" | "off" => Ok(false),
                    _ => Err(bad(name, &v, "1 or 0")),
                })
                .transpose()
        };
        Ok(Settings {
            base_url: var("BASE_URL"),
            model: var("MODEL"),
            api_key: var("API_KEY"),
            api_key_env: None,
            timeout_s: num("TIMEOUT_S")?,
            max_call_s: num("MAX_CALL_S")?,
            load_wait_s: num("LOAD_WAIT_S")?,
            connect_timeout_s: num("CONNECT_TIMEOUT_S")?,
            retries: int("RETRIES")?.map(|v| v.min(20) as u32),
            backoff_ms: int("BACKOFF_MS")?,
            max_backoff_ms: int("MAX_BACKOFF_MS")?,
            structured: flag("STRUCTURED")?,
            stream: flag("STREAM")?,
            temperature: num("TEMPERATURE")?,
            max_tokens: int("MAX_TOKENS")?.map(|v| v.min(u64::from(u32::MAX)) as u32),
            concurrency: int("CONCURRENCY")?.map(|v| v as usize),
            endpoint_concurrency: int("ENDPOINT_CONCURRENCY")?.map(|v| v as usize),
        })
    }

    fn endpoint(
        &self,
        stage: LlmStage,
        get: &dyn Fn(&str) -> Option<String>,
        source: &str,
    ) -> Result<Option<Endpoint>, ConfigError> {
        let (Some(base_url), Some(model)) = (&self.base_url, &self.model) else {
            return Ok(None);
        };
        let invalid = |message: String| ConfigError::Invalid {
            source_name: format!("{source} (stage {})", stage.name()),
            message,
        };
        if !(base_url.starts_with("http://") || base_url.starts_with("https://")) {
            return Err(invalid(format!("base_url '{base_url}' must start with http:// or https://")));
        }
        if model.trim().is_empty() {
            return Err(invalid("model must not be empty".into()));
        }
        let secs = |v: Option<f64>, default: f64, name: &str| -> Result<Duration, ConfigError> {
            let v = v.unwrap_or(default);
            if !v.is_finite() || v <= 0.0 || v > 24.0 * 3600.0 {
                return Err(invalid(format!("{name} must be between 0 and 86400 s, got {v}")));
            }
            Ok(Duration::from_secs_f64(v))
        };
        if let Some(t) = self.temperature
            && !(t.is_finite() && (0.0..=2.0).contains(&t))
        {
            return Err(invalid(format!("temperature must be in 0..2, got {t}")));
        }
        let api_key = match (&self.api_key, &self.api_key_env) {
            (Some(k), _) => Some(ApiKey::new(k.clone())),
            (None, Some(var)) => get(var).filter(|k| !k.trim().is_empty()).map(|k| ApiKey::new(k.trim())),
            (None, None) => get("OPENAI_API_KEY").filter(|k| !k.trim().is_empty()).map(|k| ApiKey::new(k.trim())),
        };
        let mut e = Endpoint::new(base_url.clone(), model.trim());
        e.api_key = api_key;
        e.timeout = secs(self.timeout_s, 60.0, "timeout_s")?;
        e.max_call = secs(self.max_call_s, 300.0, "max_call_s")?;
        e.load_wait = match self.load_wait_s {
            Some(0.0) => Duration::ZERO,
            v => secs(v, 60.0, "load_wait_s")?,
        };
        e.connect_timeout = secs(self.connect_timeout_s, 10.0, "connect_timeout_s")?;
        e.max_retries = self.retries.unwrap_or(2).min(20);
        e.backoff = Duration::from_millis(self.backoff_ms.unwrap_or(500).min(60_000));
        e.max_backoff = Duration::from_millis(self.max_backoff_ms.unwrap_or(8_000).min(300_000));
        e.structured = self.structured.unwrap_or(true);
        e.stream = self.stream.unwrap_or(true);
        e.temperature = self.temperature.or(Some(0.0));
        e.max_tokens = self.max_tokens;
        e.concurrency = self.concurrency.unwrap_or(8).clamp(1, 64);
        e.endpoint_concurrency = self.endpoint_concurrency.map(|n| n.clamp(1, 256));
        Ok(Some(e))
    }
}

impl LlmConfig {
    /// No endpoints: every stage runs offline.
    pub fn offline() -> Self {
        Self::default()
    }

    /// Sets one stage's endpoint.
    pub fn with(mut self, stage: LlmStage, endpoint: Endpoint) -> Self {
        self.endpoints.insert(stage, endpoint);
        self
    }

    /// Sets every stage's endpoint.
    pub fn with_all(mut self, endpoint: Endpoint) -> Self {
        for s in LlmStage::ALL {
            self.endpoints.insert(s, endpoint.clone());
        }
        self
    }

    pub fn endpoint(&self, stage: LlmStage) -> Option<&Endpoint> {
        self.endpoints.get(&stage)
    }

    pub fn endpoint_mut(&mut self, stage: LlmStage) -> Option<&mut Endpoint> {
        self.endpoints.get_mut(&stage)
    }

    /// True when no stage has an endpoint.
    pub fn is_offline(&self) -> bool {
        self.endpoints.is_empty()
    }

    /// The stages with an endpoint.
    pub fn stages(&self) -> impl Iterator<Item = (LlmStage, &Endpoint)> {
        self.endpoints.iter().map(|(s, e)| (*s, e))
    }

    /// From the process environment (and the file `SCENEWRIGHT_LLM_CONFIG` names).
    pub fn from_env() -> Result<Self, ConfigError> {
        Self::from_lookup(&|k| std::env::var(k).ok(), None)
    }

    /// From a file (`path`) and the process environment, which overrides it.
    pub fn from_file_and_env(path: &std::path::Path) -> Result<Self, ConfigError> {
        Self::from_lookup(&|k| std::env::var(k).ok(), Some(path))
    }

    /// From a variable lookup (the environment, or a map in tests) and an optional file.
    pub fn from_lookup(
        get: &dyn Fn(&str) -> Option<String>,
        file: Option<&std::path::Path>,
    ) -> Result<Self, ConfigError> {
        if get("SCENEWRIGHT_LLM")
            .is_some_and(|v| matches!(v.trim().to_ascii_lowercase().as_str(), "0" | "off" | "false" | "none"))
        {
            return Ok(Self::offline());
        }
        let file_path = file
            .map(|p| p.to_path_buf())
            .or_else(|| get("SCENEWRIGHT_LLM_CONFIG").filter(|v| !v.trim().is_empty()).map(Into::into));
        let from_file = match &file_path {
            None => FileSettings::default(),
            Some(p) => {
                let text = std::fs::read_to_string(p)
                    .map_err(|e| ConfigError::Unreadable { path: p.display().to_string(), reason: e.to_string() })?;
                parse_file(&text, &p.display().to_string())?
            }
        };
        let source = file_path.as_ref().map_or("environment".to_string(), |p| format!("{} / environment", p.display()));
        let env_defaults = Settings::from_env("SCENEWRIGHT_LLM_", get, "environment")?;
        let mut config = Self::offline();
        for stage in LlmStage::ALL {
            let upper = stage.name().to_ascii_uppercase();
            let env_stage = Settings::from_env(&format!("SCENEWRIGHT_LLM_{upper}_"), get, "environment")?;
            let file_stage = from_file.stages.get(stage.name()).cloned().unwrap_or_default();
            let merged = from_file.defaults.overlay(&file_stage).overlay(&env_defaults).overlay(&env_stage);
            if let Some(e) = merged.endpoint(stage, get, &source)? {
                config.endpoints.insert(stage, e);
            }
        }
        Ok(config)
    }
}

fn parse_file(text: &str, name: &str) -> Result<FileSettings, ConfigError> {
    let invalid = |message: String| ConfigError::Invalid { source_name: name.to_string(), message };
    let mut value: serde_json::Value = serde_json::from_str(text).map_err(|e| invalid(e.to_string()))?;
    let stages = value.as_object_mut().and_then(|o| o.remove("stages")).unwrap_or(serde_json::Value::Null);
    let defaults: Settings = serde_json::from_value(value).map_err(|e| invalid(e.to_string()))?;
    let stages: BTreeMap<String, Settings> = if stages.is_null() {
        BTreeMap::new()
    } else {
        serde_json::from_value(stages).map_err(|e| invalid(format!("stages: {e}")))?
    };
    let settings = FileSettings { defaults, stages };
    for k in settings.stages.keys() {
        if LlmStage::from_name(k).is_none() {
            let known: Vec<&str> = LlmStage::ALL.iter().map(|s| s.name()).collect();
            return Err(ConfigError::Invalid {
                source_name: name.to_string(),
                message: format!("unknown stage '{k}' (known: {})", known.join(", ")),
            });
        }
    }
    Ok(settings)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lookup(vars: &[(&str, &str)]) -> impl Fn(&str) -> Option<String> {
        let map: BTreeMap<String, String> = vars.iter().map(|(k, v)| (k.to_string(), v.to_string())).collect();
        move |k| map.get(k).cloned()
    }

    #[test]
    fn nothing_set_means_offline() {
        let c = LlmConfig::from_lookup(&lookup(&[]), None).unwrap();
        assert!(c.is_offline());
    }

    #[test]
    fn defaults_apply_to_every_stage_and_stages_override() {
        let c = LlmConfig::from_lookup(
            &lookup(&[
                ("SCENEWRIGHT_LLM_BASE_URL", "http://127.0.0.1:9/v1"),
                ("SCENEWRIGHT_LLM_MODEL", "m"),
                ("SCENEWRIGHT_LLM_CAD_MODEL", "coder"),
                ("SCENEWRIGHT_LLM_PLAN_TIMEOUT_S", "2.5"),
                ("OPENAI_API_KEY", "sk-test"),
            ]),
            None,
        )
        .unwrap();
        assert_eq!(c.endpoint(LlmStage::Plan).unwrap().model, "m");
        assert_eq!(c.endpoint(LlmStage::Cad).unwrap().model, "coder");
        assert_eq!(c.endpoint(LlmStage::Plan).unwrap().timeout, Duration::from_millis(2500));
        assert_eq!(c.endpoint(LlmStage::Edit).unwrap().timeout, Duration::from_secs(60));
        let key = c.endpoint(LlmStage::Plan).unwrap().api_key.clone().unwrap();
        assert_eq!(key.expose(), "sk-test");
        assert!(!format!("{:?}", c).contains("sk-test"), "keys are never printed");
        assert_eq!(c.endpoint(LlmStage::Plan).unwrap().origin(), "http://127.0.0.1:9");
    }

    #[test]
    fn a_stage_alone_can_be_configured() {
        let c = LlmConfig::from_lookup(
            &lookup(&[("SCENEWRIGHT_LLM_EDIT_BASE_URL", "https://x.invalid/v1"), ("SCENEWRIGHT_LLM_EDIT_MODEL", "e")]),
            None,
        )
        .unwrap();
        assert!(c.endpoint(LlmStage::Edit).is_some());
        assert!(c.endpoint(LlmStage::Plan).is_none());
    }

    #[test]
    fn bad_values_are_named() {
        let e = LlmConfig::from_lookup(
            &lookup(&[("SCENEWRIGHT_LLM_BASE_URL", "ftp://x"), ("SCENEWRIGHT_LLM_MODEL", "m")]),
            None,
        )
        .unwrap_err();
        assert!(e.to_string().contains("base_url 'ftp://x'"), "{e}");
        let e = LlmConfig::from_lookup(&lookup(&[("SCENEWRIGHT_LLM_TIMEOUT_S", "soon")]), None).unwrap_err();
        assert!(e.to_string().contains("SCENEWRIGHT_LLM_TIMEOUT_S"), "{e}");
    }

    #[test]
    fn the_file_holds_defaults_and_stages_and_the_environment_wins() {
        let dir = std::env::temp_dir().join(format!("sw_llm_cfg_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("llm.json");
        std::fs::write(
            &path,
            r#"{"base_url": "http://127.0.0.1:1/v1", "model": "file-model", "api_key_env": "MY_KEY",
                "stages": {"cad": {"model": "file-coder", "concurrency": 5}}}"#,
        )
        .unwrap();
        let c = LlmConfig::from_lookup(
            &lookup(&[("MY_KEY", "k1"), ("SCENEWRIGHT_LLM_PLAN_MODEL", "env-planner")]),
            Some(&path),
        )
        .unwrap();
        assert_eq!(c.endpoint(LlmStage::Plan).unwrap().model, "env-planner");
        assert_eq!(c.endpoint(LlmStage::Cad).unwrap().model, "file-coder");
        assert_eq!(c.endpoint(LlmStage::Cad).unwrap().concurrency, 5);
        assert_eq!(c.endpoint(LlmStage::Refine).unwrap().api_key.clone().unwrap().expose(), "k1");
        std::fs::write(&path, r#"{"stages": {"layout": {}}}"#).unwrap();
        let e = LlmConfig::from_lookup(&lookup(&[]), Some(&path)).unwrap_err();
        assert!(e.to_string().contains("unknown stage 'layout'"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
