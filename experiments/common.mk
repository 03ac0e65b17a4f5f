# Shared by every experiments/<id>/Makefile: where the tools are and where outputs go.
# PROFILE=quick (CI scale, minutes) or PROFILE=full (the thesis's scale).
PROFILE ?= quick
TOP := $(abspath $(dir $(lastword $(MAKEFILE_LIST)))/..)
BIN := $(TOP)/bin
OUT := out/$(PROFILE)
FIGDIR := $(TOP)/figures
SCENES := $(TOP)/sim/scenes
SHELL := /bin/bash
.SHELLFLAGS := -e -o pipefail -c
.DELETE_ON_ERROR:

# parameters of the profile: one file of key=value words, a prerequisite of every run
CONF := $(PROFILE).conf
conf = $(shell grep -v '^\s*\#' $(CONF) | grep -E '^\s*$(1)\s*=' | sed 's/^[^=]*=\s*//')

# runs of a sweep are independent: use the machine's cores unless told otherwise (a make
# started by another one, e.g. for borrowed runs, shares its parent's job slots)
ifeq ($(filter -j%,$(MAKEFLAGS) $(shell printenv MAKEFLAGS)),)
MAKEFLAGS += -j$(shell nproc)
endif
