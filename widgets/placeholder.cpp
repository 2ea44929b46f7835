// Replaced by the views.
