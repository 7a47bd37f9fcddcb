#!/usr/bin/env python3
"""An independent reference for the forge's sentence embedder (all-MiniLM-L6-v2).

The BERT encoder's forward pass written out in NumPy (float64): token + position + type
embeddings, six post-LayerNorm layers of 12-head self-attention and a GELU (erf) feed-forward
block, LayerNorm eps 1e-12; then the mean of the last layer over the attention mask and L2
normalisation, as sentence-transformers does for this model. Weights come from the same
model.safetensors (safetensors' NumPy loader), tokens from HuggingFace `tokenizers` reading
the same tokenizer.json, with its fixed 128-token padding switched off and its truncation
set to sentence-transformers' max_seq_length (sentence_bert_config.json, 256 when absent).

    minilm_reference.py MODEL_DIR < sentences.txt > vectors.jsonl

Input: one sentence per line (UTF-8). Output: one JSON object per line,
{"text": ..., "ids": [...], "vector": [...384 floats]}.

Needs the venv that `scripts/setup.sh --tests` makes (.cache/minilm-ref-venv).
"""

import json
import math
import os
import sys

import numpy as np
from safetensors.numpy import load_file
from tokenizers import Tokenizer

LAYER_NORM_EPS = 1e-12
BATCH = 8

_erf = np.frompyfunc(math.erf, 1, 1)


def gelu(x):
    """GELU in its exact form, x * Phi(x), with the error function from libm."""
    return 0.5 * x * (1.0 + _erf(x / math.sqrt(2.0)).astype(np.float64))


def layer_norm(x, gamma, beta):
    mu = x.mean(axis=-1, keepdims=True)
    var = ((x - mu) ** 2).mean(axis=-1, keepdims=True)
    return (x - mu) / np.sqrt(var + LAYER_NORM_EPS) * gamma + beta


def linear(x, w, b):
    """A torch-style dense layer: w is (out, in)."""
    return x @ w.T + b


class Encoder:
    def __init__(self, model_dir):
        with open(os.path.join(model_dir, "config.json"), encoding="utf-8") as f:
            cfg = json.load(f)
        if cfg.get("hidden_act") != "gelu" or cfg.get("position_embedding_type", "absolute") != "absolute":
            sys.exit(f"minilm_reference: unexpected config {cfg}")
        self.hidden = cfg["hidden_size"]
        self.heads = cfg["num_attention_heads"]
        self.layers = cfg["num_hidden_layers"]
        raw = load_file(os.path.join(model_dir, "model.safetensors"))
        # Some exports prefix every tensor with "bert."; accept both spellings.
        self.w = {k.removeprefix("bert."): v.astype(np.float64) for k, v in raw.items()}

    def p(self, name):
        return self.w[name]

    def forward(self, ids, mask):
        """ids, mask: (batch, tokens) int arrays; returns the last layer (batch, tokens, hidden)."""
        batch, tokens = ids.shape
        x = (
            self.p("embeddings.word_embeddings.weight")[ids]
            + self.p("embeddings.position_embeddings.weight")[np.arange(tokens)][None, :, :]
            + self.p("embeddings.token_type_embeddings.weight")[np.zeros_like(ids)]
        )
        x = layer_norm(x, self.p("embeddings.LayerNorm.weight"), self.p("embeddings.LayerNorm.bias"))
        head_dim = self.hidden // self.heads
        # Padding keys get a large negative score, so softmax gives them no weight.
        key_bias = np.where(mask[:, None, None, :] > 0, 0.0, -1e9)
        for i in range(self.layers):
            pre = f"encoder.layer.{i}."

            def split(t):
                return t.reshape(batch, tokens, self.heads, head_dim).transpose(0, 2, 1, 3)

            q = split(linear(x, self.p(pre + "attention.self.query.weight"), self.p(pre + "attention.self.query.bias")))
            k = split(linear(x, self.p(pre + "attention.self.key.weight"), self.p(pre + "attention.self.key.bias")))
            v = split(linear(x, self.p(pre + "attention.self.value.weight"), self.p(pre + "attention.self.value.bias")))
            scores = q @ k.transpose(0, 1, 3, 2) / math.sqrt(head_dim) + key_bias
            scores -= scores.max(axis=-1, keepdims=True)
            weights = np.exp(scores)
            weights /= weights.sum(axis=-1, keepdims=True)
            context = (weights @ v).transpose(0, 2, 1, 3).reshape(batch, tokens, self.hidden)
            attended = linear(
                context, self.p(pre + "attention.output.dense.weight"), self.p(pre + "attention.output.dense.bias")
            )
            x = layer_norm(
                attended + x,
                self.p(pre + "attention.output.LayerNorm.weight"),
                self.p(pre + "attention.output.LayerNorm.bias"),
            )
            inner = gelu(linear(x, self.p(pre + "intermediate.dense.weight"), self.p(pre + "intermediate.dense.bias")))
            out = linear(inner, self.p(pre + "output.dense.weight"), self.p(pre + "output.dense.bias"))
            x = layer_norm(out + x, self.p(pre + "output.LayerNorm.weight"), self.p(pre + "output.LayerNorm.bias"))
        return x


def sentence_vectors(hidden, mask):
    m = mask[:, :, None].astype(np.float64)
    mean = (hidden * m).sum(axis=1) / np.maximum(m.sum(axis=1), 1e-9)
    return mean / np.maximum(np.linalg.norm(mean, axis=1, keepdims=True), 1e-12)


def max_seq_length(model_dir):
    path = os.path.join(model_dir, "sentence_bert_config.json")
    if os.path.exists(path):
        with open(path, encoding="utf-8") as f:
            return int(json.load(f)["max_seq_length"])
    return 256


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: minilm_reference.py MODEL_DIR < sentences.txt")
    model_dir = sys.argv[1]
    tokenizer = Tokenizer.from_file(os.path.join(model_dir, "tokenizer.json"))
    tokenizer.no_padding()
    tokenizer.enable_truncation(max_length=max_seq_length(model_dir))
    encoder = Encoder(model_dir)
    texts = [line.rstrip("\r\n") for line in sys.stdin.read().split("\n")]
    if texts and texts[-1] == "":
        texts.pop()
    out = sys.stdout
    for start in range(0, len(texts), BATCH):
        chunk = texts[start : start + BATCH]
        encodings = [tokenizer.encode(t).ids for t in chunk]
        # Pad the batch to its longest input ourselves, so the mask path is exercised.
        width = max(len(e) for e in encodings)
        ids = np.zeros((len(chunk), width), dtype=np.int64)
        mask = np.zeros((len(chunk), width), dtype=np.int64)
        for row, e in enumerate(encodings):
            ids[row, : len(e)] = e
            mask[row, : len(e)] = 1
        vectors = sentence_vectors(encoder.forward(ids, mask), mask)
        for text, e, v in zip(chunk, encodings, vectors):
            out.write(json.dumps({"text": text, "ids": e, "vector": [float(x) for x in v]}, ensure_ascii=False))
            out.write("\n")
    out.flush()


if __name__ == "__main__":
    main()
