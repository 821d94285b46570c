/* placeholder: implemented by the predicates work */
