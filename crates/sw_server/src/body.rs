//! A JSON body extractor whose rejections are clear `{"error": ...}` answers.

use axum::extract::rejection::JsonRejection;
use axum::extract::{FromRequest, Request};
use axum::http::StatusCode;
use serde::de::DeserializeOwned;

use crate::error::ApiError;

/// `Json<T>` with the service's error shape: malformed JSON 400, wrong types or unknown
/// fields 422, no JSON content type 415, a body over the limit 413.
#[derive(Debug)]
pub struct Body<T>(pub T);

impl<S, T> FromRequest<S> for Body<T>
where
    T: DeserializeOwned,
    S: Send + Sync,
{
    type Rejection = ApiError;

    async fn from_request(req: Request, state: &S) -> Result<Self, Self::Rejection> {
        match axum::Json::<T>::from_request(req, state).await {
            Ok(axum::Json(v)) => Ok(Body(v)),
            Err(r) => Err(rejection(r)),
        }
    }
}

fn rejection(r: JsonRejection) -> ApiError {
    let status = r.status();
    let message = match &r {
        JsonRejection::JsonSyntaxError(_) => format!("malformed JSON: {}", r.body_text()),
        JsonRejection::JsonDataError(_) => format!("the JSON does not fit: {}", r.body_text()),
        JsonRejection::MissingJsonContentType(_) => "send the body as JSON (Content-Type: application/json)".into(),
        _ if status == StatusCode::PAYLOAD_TOO_LARGE => {
            format!("the body is larger than the {} KiB limit", crate::BODY_LIMIT / 1024)
        }
        _ => r.body_text(),
    };
    ApiError::new(status, message)
}
