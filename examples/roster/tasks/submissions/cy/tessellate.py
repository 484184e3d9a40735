#!/usr/bin/env python3
"""Cy's curve task: it dies on the first record it reads (a null pointer in the C it was ported from)."""
import os

os.abort()
