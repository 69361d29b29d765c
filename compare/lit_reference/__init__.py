"""What the VTK reference needs to know per reflection model, one module each, found through
:mod:`compare.lit_reference.lit_registry`. Importing the package loads nothing."""
