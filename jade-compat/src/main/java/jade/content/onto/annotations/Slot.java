package jade.content.onto.annotations;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * How a bean property (annotate its getter) maps to a slot of a {@link jade.content.onto.BeanOntology}
 * schema, as in JADE. Read here: {@link #name()}, {@link #mandatory()}, {@link #position()}; the
 * others are accepted and not enforced.
 */
@Retention(RetentionPolicy.RUNTIME)
@Target({ElementType.METHOD, ElementType.FIELD})
public @interface Slot {
    /** The default of {@link #name()}: the property's name. */
    String USE_METHOD_NAME = "__USE_METHOD_NAME__";
    /** The "no value" of the string attributes. */
    String NULL = "__NULL__";

    /** The slot's name. */
    String name() default USE_METHOD_NAME;

    /** Documentation (not used). */
    String documentation() default NULL;

    /** The slot's place when the element is encoded by order; -1 for none. */
    int position() default -1;

    /** Whether the slot must have a value. */
    boolean mandatory() default false;

    /** JADE: send the value as a serialized Java object (not supported: the slot is refused). */
    boolean manageAsSerializable() default false;

    /** A default value (not used). */
    String defaultValue() default NULL;

    /** A pattern the value must match (not enforced). */
    String regex() default NULL;

    /** The values allowed (not enforced). */
    String[] permittedValues() default {};
}
