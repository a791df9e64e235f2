import jade.content.Concept;

/** The bean of a hand-written schema whose slots are named in capitals (FATHER, NAME), as JADE's content example names them. */
public class Person implements Concept {
    private String name;
    private Person father;
    private long age;

    public String getName() {
        return name;
    }

    public void setName(String name) {
        this.name = name;
    }

    public Person getFather() {
        return father;
    }

    public void setFather(Person father) {
        this.father = father;
    }

    public long getAge() {
        return age;
    }

    public void setAge(long age) {
        this.age = age;
    }
}
