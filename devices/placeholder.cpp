// Replaced by the device layer.
