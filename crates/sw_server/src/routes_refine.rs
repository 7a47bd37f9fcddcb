//! `POST /api/refine {prompt, turns: [{question, answer}]}`: one turn of the refinement
//! chat. The service keeps no conversation: the page sends the transcript so far and gets
//! the next question, or — when the prompt is specified enough, or the user answered
//! "done" — the final prompt with a summary of how it will be read. The questions are the
//! offline planner's, or the REFINE stage model's when one is configured (the offline
//! questions take over if it fails, and the answer says so).

use axum::Json;
use axum::extract::State;
use axum::http::StatusCode;
use serde::Deserialize;
use serde_json::{Value, json};
use sw_llm::LlmStage;
use sw_pipeline::{Refiner, Turn};

use crate::AppState;
use crate::auth::Caller;
use crate::body::Body;
use crate::error::{ApiError, ApiResult};

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TurnIn {
    question: String,
    answer: String,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RefineRequest {
    #[serde(default)]
    prompt: String,
    #[serde(default)]
    turns: Vec<TurnIn>,
}

fn summary(plan: &sw_plan::ScenePlan) -> String {
    let objects: Vec<String> = plan.objects.iter().map(|o| format!("{} × {}", o.count, o.phrase)).collect();
    let robots: Vec<String> = plan.robots.iter().map(|r| format!("{} × {}", r.count, r.model)).collect();
    let s = plan.room.size;
    format!(
        "Read as: a {} of {:.1} × {:.1} m; {}{}",
        plan.room.kind.name().replace('_', " "),
        s.width,
        s.depth,
        if objects.is_empty() { "no objects".to_string() } else { objects.join(", ") },
        if robots.is_empty() { String::new() } else { format!("; robots: {}", robots.join(", ")) }
    )
}

pub async fn refine(
    State(s): State<AppState>,
    _caller: Caller,
    Body(r): Body<RefineRequest>,
) -> ApiResult<Json<Value>> {
    if r.prompt.len() > crate::PROMPT_LIMIT {
        return Err(ApiError::new(StatusCode::PAYLOAD_TOO_LARGE, "the prompt is too long"));
    }
    if r.turns.len() > sw_pipeline::REFINE_MAX_TURNS + 1 {
        return Err(ApiError::new(
            StatusCode::UNPROCESSABLE_ENTITY,
            "the conversation has more turns than a refinement asks",
        ));
    }
    if r.turns.iter().any(|t| t.question.len() > 4096 || t.answer.len() > 8192) {
        return Err(ApiError::new(StatusCode::PAYLOAD_TOO_LARGE, "a question or answer is too long"));
    }
    let turns: Vec<Turn> = r.turns.into_iter().map(|t| Turn { question: t.question, answer: t.answer }).collect();
    let client = s.runner.llm.clone().filter(|c| c.endpoint(LlmStage::Refine).is_some()).map(sw_llm::Client::new);
    let planner = s.runner.llm.clone().filter(|c| c.endpoint(LlmStage::Plan).is_some()).map(sw_llm::Client::new);
    let prompt = r.prompt;
    // The model's calls block: off the async threads.
    let answer = tokio::task::spawn_blocking(move || -> ApiResult<Value> {
        let mut refiner = Refiner::resume(&prompt, &turns, client);
        if let Some(q) = refiner.next_question() {
            let warnings: Vec<&str> = refiner.warnings().iter().map(|w| w.message.as_str()).collect();
            return Ok(json!({
                "done": false, "question": q, "prompt": refiner.prompt(), "asked_by": refiner.asked_by(),
                "turns": refiner.transcript(), "warnings": warnings,
            }));
        }
        let done = refiner.finish(planner.as_ref()).map_err(|e| match e {
            sw_pipeline::PipelineError::Input(m) => ApiError::new(StatusCode::UNPROCESSABLE_ENTITY, m),
            e => ApiError::internal(e),
        })?;
        let warnings: Vec<&str> = done.warnings.iter().map(|w| w.message.as_str()).collect();
        Ok(json!({
            "done": true, "question": null, "prompt": done.prompt, "asked_by": done.asked_by,
            "turns": done.transcript, "task": done.task, "summary": summary(&done.plan), "warnings": warnings,
        }))
    })
    .await
    .map_err(ApiError::internal)??;
    Ok(Json(answer))
}
