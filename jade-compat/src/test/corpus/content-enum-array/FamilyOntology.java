import jade.content.onto.BasicOntology;
import jade.content.onto.Ontology;
import jade.content.onto.OntologyException;
import jade.content.schema.ConceptSchema;
import jade.content.schema.ObjectSchema;
import jade.content.schema.PrimitiveSchema;

/** Slots named in capitals, read and written through getName/getFather/getAge: JADE finds accessors ignoring case. */
public class FamilyOntology extends Ontology {
    public static final String NAME = "family";

    public FamilyOntology() {
        super(NAME, BasicOntology.getInstance());
        try {
            ConceptSchema person = new ConceptSchema("PERSON");
            add(person, Person.class);
            person.add("NAME", (PrimitiveSchema) getSchema(BasicOntology.STRING));
            person.add("AGE", (PrimitiveSchema) getSchema(BasicOntology.INTEGER), ObjectSchema.OPTIONAL);
            person.add("FATHER", person, ObjectSchema.OPTIONAL);
        } catch (OntologyException e) {
            e.printStackTrace();
        }
    }
}
