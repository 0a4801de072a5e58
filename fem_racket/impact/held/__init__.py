"""The hand-held racket: the frame with a hand on its grip, its exact modes and impacts, and the
handle shock."""
