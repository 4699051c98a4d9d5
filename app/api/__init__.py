"""The HTTP edge: thin routes that validate, call one service or domain function, map the result."""
