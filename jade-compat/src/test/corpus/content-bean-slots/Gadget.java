import jade.content.Concept;
import jade.content.onto.annotations.AggregateSlot;
import jade.content.onto.annotations.Element;
import jade.content.onto.annotations.Slot;
import jade.content.onto.annotations.SuppressSlot;

import java.util.Date;
import java.util.List;
import java.util.Set;

/** A bean with a slot of each kind a BeanOntology maps (but byte[]: JADE's SL needs commons-codec for it, not on the corpus's class path). */
@Element(name = "gizmo")
public class Gadget implements Concept {
    private String name;
    private boolean active;
    private Boolean flag;
    private double weight;
    private long id;
    private Date made;
    private Set<String> tags;
    private jade.util.leap.List parts;
    private List<Integer> numbers;
    private Object any;
    private Part main;
    private String secret;

    @Slot(name = "gadget-name", mandatory = true)
    public String getName() {
        return name;
    }

    public void setName(String name) {
        this.name = name;
    }

    public boolean isActive() {
        return active;
    }

    public void setActive(boolean active) {
        this.active = active;
    }

    public Boolean getFlag() {
        return flag;
    }

    public void setFlag(Boolean flag) {
        this.flag = flag;
    }

    public double getWeight() {
        return weight;
    }

    public void setWeight(double weight) {
        this.weight = weight;
    }

    public long getId() {
        return id;
    }

    public void setId(long id) {
        this.id = id;
    }

    public Date getMade() {
        return made;
    }

    public void setMade(Date made) {
        this.made = made;
    }

    public Set<String> getTags() {
        return tags;
    }

    public void setTags(Set<String> tags) {
        this.tags = tags;
    }

    @AggregateSlot(type = Part.class, cardMax = 3)
    public jade.util.leap.List getParts() {
        return parts;
    }

    public void setParts(jade.util.leap.List parts) {
        this.parts = parts;
    }

    public List<Integer> getNumbers() {
        return numbers;
    }

    public void setNumbers(List<Integer> numbers) {
        this.numbers = numbers;
    }

    public Object getAny() {
        return any;
    }

    public void setAny(Object any) {
        this.any = any;
    }

    public Part getMain() {
        return main;
    }

    public void setMain(Part main) {
        this.main = main;
    }

    @SuppressSlot
    public String getSecret() {
        return secret;
    }

    public void setSecret(String secret) {
        this.secret = secret;
    }
}
